#pragma once
// Errors the command line turns into a one-line message and an exit code.
#include <stdexcept>
#include <string>

namespace brdfkit {

// Bad input (file, field or parameter): message names what is wrong; exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& what) : std::runtime_error(where + ": " + what) {}
};

}  // namespace brdfkit
