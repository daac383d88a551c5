#include "brdfkit/core/json_text.h"

#include <optional>
#include <utility>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"

namespace brdfkit {

namespace {

// The pointer and text of the first string of `j` (keys included) that is not valid UTF-8.
std::optional<std::pair<std::string, std::string>> first_bad_string(const nlohmann::json& j, const std::string& at) {
  if (j.is_string()) {
    const auto& s = j.get_ref<const std::string&>();
    if (!is_valid_utf8(s)) return std::pair{at.empty() ? std::string("/") : at, s};
  } else if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (!is_valid_utf8(key)) return std::pair{at + "/" + key, key};
      if (auto bad = first_bad_string(value, at + "/" + key)) return bad;
    }
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i)
      if (auto bad = first_bad_string(j[i], at + "/" + std::to_string(i))) return bad;
  }
  return std::nullopt;
}

[[noreturn]] void refuse(const std::string& text, const std::string& at) {
  throw InputError(text, "not valid UTF-8, which JSON output cannot hold" + (at.empty() ? "" : " (at " + at + ")") +
                             "; use a UTF-8 name");
}

}  // namespace

void require_json_text(const std::string& text) {
  if (!is_valid_utf8(text)) refuse(text, "");
}

std::string json_text(const nlohmann::json& doc, int indent) {
  try {
    return doc.dump(indent);
  } catch (const nlohmann::json::type_error& e) {
    if (e.id != 316) throw;  // 316: a string that is not UTF-8
    const auto bad = first_bad_string(doc, "");
    if (!bad) throw;
    refuse(bad->second, bad->first);
  }
}

}  // namespace brdfkit
