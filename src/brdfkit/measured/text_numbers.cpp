#include "brdfkit/measured/text_numbers.h"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "brdfkit/core/error.h"

namespace brdfkit {

std::vector<double> parse_numbers(const std::string& line, const std::string& where) {
  std::vector<double> v;
  std::istringstream ss(line);
  std::string tok;
  while (ss >> tok) {
    size_t used = 0;
    double x = 0;
    try {
      x = std::stod(tok, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tok.size() || !std::isfinite(x)) throw InputError(where, fmt::format("not a number: '{}'", tok));
    v.push_back(x);
  }
  return v;
}

}  // namespace brdfkit
