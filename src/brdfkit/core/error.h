#pragma once
// Errors that interfaces (the command line, Python) turn into a one-line message: bad input names
// the file, field or parameter; a bad setting names the setting and what it accepts. Both hold
// their text through printable() (core/text.h): names read from files or typed by users may carry
// NUL or control bytes, which would cut what() short or act on the terminal.
#include <stdexcept>
#include <string>

#include "brdfkit/core/text.h"

namespace brdfkit {

// Bad input (file, field or parameter): the message names what is wrong; exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(printable(where) + ": " + printable(what)) {}
};

// A setting outside what it accepts. `setting` is the library's name of it (`max_iterations`):
// the command line shows it as its flag (`--max-iterations`), Python as its keyword argument.
class SettingError : public InputError {
 public:
  SettingError(const std::string& setting, const std::string& detail)
      : InputError(setting, detail), setting_(printable(setting)), detail_(printable(detail)) {}
  const std::string& setting() const { return setting_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string setting_, detail_;
};

}  // namespace brdfkit
