#include "brdfkit/core/text.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace brdfkit {

namespace {

// Length of the well-formed UTF-8 sequence at text[i] (1 to 4), or 0 when the bytes there are not one.
size_t utf8_sequence_length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t b0 = byte(i);
  if (b0 < 0x80) return 1;
  size_t n = 0;
  std::uint8_t lo = 0x80, hi = 0xbf;  // allowed range of the second byte (excludes overlongs, surrogates, > U+10FFFF)
  if (b0 >= 0xc2 && b0 <= 0xdf) n = 2;
  else if (b0 >= 0xe0 && b0 <= 0xef) n = 3, lo = b0 == 0xe0 ? 0xa0 : 0x80, hi = b0 == 0xed ? 0x9f : 0xbf;
  else if (b0 >= 0xf0 && b0 <= 0xf4) n = 4, lo = b0 == 0xf0 ? 0x90 : 0x80, hi = b0 == 0xf4 ? 0x8f : 0xbf;
  else return 0;
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  return n;
}

void append_escaped(std::string& out, std::uint8_t b) {
  static const char* hex = "0123456789abcdef";
  switch (b) {
    case '\n': out += "\\n"; return;
    case '\r': out += "\\r"; return;
    case '\t': out += "\\t"; return;
    default:
      out += "\\x";
      out += hex[b >> 4];
      out += hex[b & 15];
  }
}

}  // namespace

bool is_valid_utf8(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8_sequence_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const auto b0 = static_cast<std::uint8_t>(text[i]);
    const size_t n = utf8_sequence_length(text, i);
    const bool c1_control = n == 2 && b0 == 0xc2 && static_cast<std::uint8_t>(text[i + 1]) < 0xa0;
    if (n == 0 || (n == 1 && (b0 < 0x20 || b0 == 0x7f))) {
      append_escaped(out, b0);
      i += 1;
    } else if (c1_control) {
      append_escaped(out, b0);
      append_escaped(out, static_cast<std::uint8_t>(text[i + 1]));
      i += 2;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

std::optional<double> finite_number(const std::string& token) {
  size_t used = 0;
  double x = 0;
  try {
    x = std::stod(token, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != token.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace brdfkit
