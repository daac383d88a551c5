#pragma once
// Matching the command line's output by whole lines and whitespace-separated tokens: a bare
// substring search passes on any text that happens to contain it ("he" in "the").
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace brdfkit::test {

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

inline std::vector<std::string> tokens_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

// Whether one line of `text` equals `line` exactly.
inline bool has_line(const std::string& text, const std::string& line) {
  for (const auto& l : lines_of(text))
    if (l == line) return true;
  return false;
}

// The first line whose first whitespace-separated token is `token`.
inline std::optional<std::string> line_led_by(const std::string& text, const std::string& token) {
  for (const auto& l : lines_of(text)) {
    const auto t = tokens_of(l);
    if (!t.empty() && t[0] == token) return l;
  }
  return std::nullopt;
}

// The first line that starts with `prefix` (characters, not tokens).
inline std::optional<std::string> line_starting(const std::string& text, const std::string& prefix) {
  for (const auto& l : lines_of(text))
    if (l.rfind(prefix, 0) == 0) return l;
  return std::nullopt;
}

}  // namespace brdfkit::test
