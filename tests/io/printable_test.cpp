// The one byte escaper: every byte value, random byte strings decoded back by a slow twin, the
// cut, and the quotes.

#include "io/printable.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

namespace cardemo {
namespace {

// Slow twin: undoes printable() (no cut), or returns "<bad>" when the text is not its output.
std::string unescapePrintable(const std::string& text) {
  std::string bytes;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20 || u >= 0x7f) return "<bad>";
    if (text.compare(i, 2, "\\x") != 0) {
      bytes += text[i];
      continue;
    }
    if (i + 4 > text.size()) return "<bad>";
    const std::string hex = text.substr(i + 2, 2);
    if (hex.find_first_not_of("0123456789abcdef") != std::string::npos) return "<bad>";
    bytes += static_cast<char>(std::stoi(hex, nullptr, 16));
    i += 3;
  }
  return bytes;
}

TEST(Printable, KeepsPrintableAsciiAndEscapesEveryOtherByte) {
  for (int b = 0; b < 256; ++b) {
    const std::string one(1, static_cast<char>(b));
    const std::string out = printable(one);
    if (b >= 0x20 && b < 0x7f) {
      EXPECT_EQ(out, one) << b;
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      EXPECT_EQ(out, std::string("\\x") + kHex[b >> 4] + kHex[b & 15]) << b;
    }
  }
  EXPECT_EQ(printable(std::string("a\0b\n\x7f\xff", 6)), "a\\x00b\\x0a\\x7f\\xff");
  EXPECT_EQ(printable(""), "");
}

TEST(Printable, RandomBytesComeBackFromTheEscapedText) {
  std::mt19937 rng(40);
  std::uniform_int_distribution<int> byte(0, 255), length(0, 60);
  for (int n = 0; n < 2000; ++n) {
    std::string bytes(static_cast<std::size_t>(length(rng)), '\0');
    // Half the cases printable text with a few odd bytes, half any bytes.
    for (char& c : bytes) {
      const bool letter = n % 2 == 0 && byte(rng) < 230;
      c = static_cast<char>(letter ? 'a' + byte(rng) % 26 : byte(rng));
    }
    // A backslash followed by 'x' would be ambiguous in the twin; printable leaves it as it is.
    const std::string out = printable(bytes, bytes.size());
    if (bytes.find("\\x") == std::string::npos) {
      EXPECT_EQ(unescapePrintable(out), bytes) << out;
    }
    for (const char c : out) {
      ASSERT_TRUE(c >= 0x20 && c < 0x7f) << out;
    }
  }
}

TEST(Printable, CutsAfterMaxBytesOfInput) {
  EXPECT_EQ(printable("abcdef", 3), "abc...");
  EXPECT_EQ(printable("abc", 3), "abc");
  EXPECT_EQ(printable(std::string("\x01\x02\x03\x04", 4), 2), "\\x01\\x02...");
  EXPECT_EQ(printable(std::string(48, 'k')), std::string(48, 'k'));
  EXPECT_EQ(printable(std::string(49, 'k')), std::string(48, 'k') + "...");
}

TEST(Printable, InQuotesWrapsTheSameText) {
  EXPECT_EQ(inQuotes("A1"), "\"A1\"");
  EXPECT_EQ(inQuotes(std::string("\r", 1)), "\"\\x0d\"");
  EXPECT_EQ(inQuotes(std::string(41, 'z')), "\"" + std::string(40, 'z') + "...\"");
  EXPECT_EQ(inQuotes("abcd", 2), "\"ab...\"");
}

}  // namespace
}  // namespace cardemo
