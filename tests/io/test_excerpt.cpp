/// @file
/// Quotes of input in messages stay short and printable whatever the input.

#include <gtest/gtest.h>

#include <string>

#include "tailor/io/excerpt.hpp"

namespace tailor {
namespace {

TEST(Excerpt, KeepsShortPrintableTextAsIs) {
  EXPECT_EQ(excerpt("garbage"), "garbage");
  EXPECT_EQ(excerpt(""), "");
  EXPECT_EQ(excerpt(std::string(40, 'a')), std::string(40, 'a'));
}

TEST(Excerpt, CutsLongTextAndSaysHowLongItWas) {
  const std::string huge(10'000'000, 'x');
  const std::string quote = excerpt(huge);
  EXPECT_EQ(quote, std::string(40, 'x') + "... (10000000 bytes)");
}

TEST(Excerpt, EscapesControlAndHighBytes) {
  EXPECT_EQ(excerpt(std::string("a\0b\n\xff", 5)), "a\\x00b\\x0a\\xff");
  // An escape is never split: 40 bytes hold ten of them.
  std::string ten_escapes;
  for (int i = 0; i < 10; ++i) ten_escapes += "\\x00";
  EXPECT_EQ(excerpt(std::string(100, '\0')), ten_escapes + "... (100 bytes)");
}

}  // namespace
}  // namespace tailor
