#pragma once
// Text from outside (file names, names read from files, arguments) may hold any bytes. Messages
// show it through printable(), so a NUL cannot cut a line short and a control byte cannot act on
// the terminal; JSON output needs it to be UTF-8 (is_valid_utf8).
#include <optional>
#include <string>
#include <string_view>

namespace brdfkit {

// True when `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF),
// which is what JSON output can hold.
bool is_valid_utf8(std::string_view text);

// `text` with every control byte (C0, DEL, and the C1 controls U+0080–U+009F) and every byte outside
// well-formed UTF-8 written as an escape: \n, \r, \t, else \xNN. Other UTF-8 (θ, §) stays as it is.
// The result holds only printable text, so applying it twice changes nothing.
std::string printable(std::string_view text);

// The number that `token` holds in full, in std::stod's syntax; nullopt when the token holds
// anything else (nothing, trailing characters) or a value that is not finite.
std::optional<double> finite_number(const std::string& token);

}  // namespace brdfkit
