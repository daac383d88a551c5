#pragma once
// Whitespace-separated numbers of one line of a text format (Cornell, ALTA).
#include <string>
#include <vector>

namespace brdfkit {

// Every token must be a finite number; InputError naming `where` (file and line) otherwise.
std::vector<double> parse_numbers(const std::string& line, const std::string& where);

}  // namespace brdfkit
