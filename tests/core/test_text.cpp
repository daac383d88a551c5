// printable() and is_valid_utf8() (core/text.h): what messages and JSON output rely on.
#include <gtest/gtest.h>

#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"

namespace brdfkit {
namespace {

using namespace std::string_literals;

TEST(Text, PrintableEscapesControlAndStrayBytesAndKeepsUtf8) {
  EXPECT_EQ(printable("no\0such\x1b[2J"s), "no\\x00such\\x1b[2J");
  EXPECT_EQ(printable("a\nb\rc\td\x7f"), "a\\nb\\rc\\td\\x7f");
  EXPECT_EQ(printable("caf\xe9.binary"), "caf\\xe9.binary");      // Latin-1 é: not UTF-8
  EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\xc2\\x9b31m");          // C1 control CSI, though valid UTF-8
  EXPECT_EQ(printable("θh ≤ 90° §2 \\x41"), "θh ≤ 90° §2 \\x41");  // text and backslashes stay
  const std::string once = printable("x\0\xff\n"s);
  EXPECT_EQ(printable(once), once);
}

TEST(Text, Utf8ValidationRejectsWhatJsonRejects) {
  EXPECT_TRUE(is_valid_utf8("plain, θ, 😀"));
  EXPECT_TRUE(is_valid_utf8("nul \0 is valid"s));
  EXPECT_FALSE(is_valid_utf8("caf\xe9"));
  EXPECT_FALSE(is_valid_utf8("\xc0\xaf"));          // overlong '/'
  EXPECT_FALSE(is_valid_utf8("\xed\xa0\x80"));      // surrogate U+D800
  EXPECT_FALSE(is_valid_utf8("\xf4\x90\x80\x80"));  // past U+10FFFF
  EXPECT_FALSE(is_valid_utf8("\xe2\x82"));          // cut short
}

TEST(Text, InputErrorKeepsTheWholeMessage) {
  const InputError e("file\0name"s, "field 'a\nb'");
  EXPECT_STREQ(e.what(), "file\\x00name: field 'a\\nb'");
}

}  // namespace
}  // namespace brdfkit
