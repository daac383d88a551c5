#pragma once
// JSON output of documents that carry names from outside (file and material names): the file
// system allows any bytes in a name, JSON only UTF-8 text, so a name that is not UTF-8 is bad
// input to name, not an internal error.
#include <nlohmann/json.hpp>
#include <string>

namespace brdfkit {

// doc.dump(indent). InputError naming the first string (value or key) that is not valid UTF-8
// and where it sits in the document (a JSON pointer such as /data/file).
std::string json_text(const nlohmann::json& doc, int indent = 2);

// The same InputError for one name (a file or material name) that is not valid UTF-8: checked
// before long work whose result is JSON, so it fails at once rather than at the end.
void require_json_text(const std::string& text);

}  // namespace brdfkit
