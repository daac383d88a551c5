#include "brdfkit/measured/text_numbers.h"

#include <sstream>

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"

namespace brdfkit {

std::vector<double> parse_numbers(const std::string& line, const std::string& where) {
  std::vector<double> v;
  std::istringstream ss(line);
  std::string tok;
  while (ss >> tok) {
    const std::optional<double> x = finite_number(tok);
    if (!x) throw InputError(where, fmt::format("not a number: '{}'", tok));
    v.push_back(*x);
  }
  return v;
}

}  // namespace brdfkit
