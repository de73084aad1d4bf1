// numberText, fixedText and readNumber against the standard library's floating-point to_chars and
// from_chars (which the native builds have), on seeded random doubles and named edge cases.
#include "io/number_text.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "../support/test_scale.hpp"
#include "geometry/bit_cast.hpp"

namespace cardemo {
namespace {

using testing::scaledCount;

std::string standardShortest(double v) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, v);
  return {text, result.ptr};
}

std::string standardFixed(double v, int decimals) {
  char text[512];
  const auto result =
      std::to_chars(text, text + sizeof text, v, std::chars_format::fixed, decimals);
  return {text, result.ptr};
}

// Any finite double, every exponent equally likely (subnormals included).
double anyFinite(std::mt19937_64& rng) {
  for (;;) {
    const double v = bitCast<double>(rng());
    if (std::isfinite(v)) return v;
  }
}

// Doubles that printf and to_chars treat specially: exact powers of two (whose rounding interval
// is narrower below than above), short decimals, integers around 2^53 and 1e17..1e23 (where
// fixed and scientific change places), the extremes and their neighbours.
std::vector<double> namedValues() {
  std::vector<double> v = {0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           0.1,
                           0.3,
                           1e-3,
                           1e-4,
                           1e5,
                           123456.0,
                           1e15,
                           1e16,
                           1e21,
                           1e22,
                           1e23,
                           5e-324,
                           -5e-324,
                           2.2250738585072009e-308,
                           2.2250738585072014e-308,
                           1.7976931348623157e308,
                           -1.7976931348623157e308,
                           9007199254740992.0,
                           9007199254740994.0,
                           123456789012345680.0,
                           1152921504606846976.0,
                           0x1p-1022,
                           0x1.fffffffffffffp-1,
                           3.14159265358979323846};
  for (int e = -1074; e <= 1023; ++e) v.push_back(std::ldexp(1.0, e));
  for (int e = -325; e <= 308; ++e)
    v.push_back(std::strtod(("1e" + std::to_string(e)).c_str(), nullptr));
  const std::vector<double> copy = v;
  for (const double x : copy) {
    v.push_back(std::nextafter(x, std::numeric_limits<double>::infinity()));
    v.push_back(std::nextafter(x, -std::numeric_limits<double>::infinity()));
  }
  return v;
}

std::vector<double> randomValues(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> world(-1e7, 1e7);
  std::uniform_int_distribution<std::int64_t> integer(-(std::int64_t{1} << 62),
                                                      std::int64_t{1} << 62);
  std::uniform_int_distribution<int> places(0, 17);
  std::vector<double> v;
  for (int i = 0; i < count; ++i) {
    switch (i % 5) {
      case 0:
      case 1:
        v.push_back(anyFinite(rng));
        break;
      case 2:
        v.push_back(world(rng));
        break;
      case 3:
        v.push_back(static_cast<double>(integer(rng) >> places(rng)));
        break;
      default:  // a short decimal: an integer over a power of ten
        v.push_back(static_cast<double>(integer(rng) >> (3 * places(rng))) /
                    std::pow(10.0, places(rng)));
        break;
    }
  }
  return v;
}

TEST(NumberText, ShortestMatchesToCharsOnNamedValues) {
  for (const double v : namedValues()) {
    ASSERT_EQ(numberText(v), standardShortest(v)) << std::hexfloat << v;
  }
}

TEST(NumberText, ShortestMatchesToCharsOnRandomDoubles) {
  for (const double v : randomValues(41, scaledCount(300000))) {
    ASSERT_EQ(numberText(v), standardShortest(v)) << std::hexfloat << v;
  }
}

TEST(NumberText, ShortestMatchesToCharsOnRoundingTies) {
  // Short decimals that lie exactly halfway between two doubles: n * 10^k = (n 5^k) 2^k with
  // n 5^k odd and in [2^53, 2^54) is an odd multiple of half the ulp there (2^(k+1)). It reads
  // back as the neighbour whose significand is even, so the shortest text of the other one needs
  // more digits.
  int ties = 0;
  for (const int k : {8, 10, 12, 15, 18, 20, 21}) {
    const double five = std::pow(5.0, k);  // exact: 5^21 < 2^53
    const auto first = static_cast<std::int64_t>(std::ceil(0x1p53 / five)) | 1;
    for (std::int64_t n = first; static_cast<double>(n) * five < 0x1p54 && n < first + 1000;
         n += 2) {
      const std::string text = std::to_string(n) + "e" + std::to_string(k);
      const double even = std::strtod(text.c_str(), nullptr);
      for (const double v : {even, std::nextafter(even, 0.0), std::nextafter(even, 1e300)}) {
        ASSERT_EQ(numberText(v), standardShortest(v)) << std::hexfloat << v << " near " << text;
      }
      ++ties;
    }
  }
  EXPECT_GT(ties, 2000);
}

TEST(NumberText, NonFinite) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  for (const double v : {kInf, -kInf, kNan, -kNan}) {
    EXPECT_EQ(numberText(v), standardShortest(v));
    EXPECT_EQ(fixedText(v, 2), standardFixed(v, 2));
  }
}

TEST(NumberText, FixedMatchesToChars) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> decimals(0, 20);
  std::vector<double> values = randomValues(43, scaledCount(100000));
  // Exact ties at two decimals (to even) and at none.
  for (const double tie : {0.125, 0.375, -0.125, 2.5, 3.5, -2.5, 0.5, 1.5, 1e22 + 0.0}) {
    values.push_back(tie);
  }
  for (const double v : values) {
    if (std::abs(v) > 1e30) continue;  // long, and no caller prints such numbers fixed
    const int d = decimals(rng);
    ASSERT_EQ(fixedText(v, d), standardFixed(v, d)) << std::hexfloat << v << " " << d;
    ASSERT_EQ(fixedText(v, 2), standardFixed(v, 2)) << std::hexfloat << v;
  }
  EXPECT_EQ(fixedText(0.125, 2), "0.12");
  EXPECT_EQ(fixedText(-0.0, 1), "-0.0");
  EXPECT_EQ(fixedText(1e300, 0), standardFixed(1e300, 0));
}

// readNumber and from_chars agree on the error, the length read and the value's bits.
void expectSameRead(const std::string& text) {
  double mine = -7.0;
  double standard = -7.0;
  const NumberRead read = readNumber(text, mine);
  const auto result = std::from_chars(text.data(), text.data() + text.size(), standard);
  ASSERT_EQ(read.error, result.ec) << '"' << text << '"';
  ASSERT_EQ(read.length, static_cast<std::size_t>(result.ptr - text.data())) << '"' << text << '"';
  if (std::isnan(standard)) {
    ASSERT_TRUE(std::isnan(mine)) << text;
    ASSERT_EQ(std::signbit(mine), std::signbit(standard)) << text;
  } else {
    ASSERT_EQ(bitCast<std::uint64_t>(mine), bitCast<std::uint64_t>(standard)) << '"' << text << '"';
  }
}

TEST(NumberText, ReadMatchesFromCharsOnNamedTexts) {
  for (const char* text : {"1e400",
                           "-1e400",
                           "1e-400",
                           "-1e-400",
                           "4.9e-324",
                           "2.4703282292062327e-324",
                           "2.4703282292062328e-324",
                           "1e-320",
                           "2.2250738585072011e-308",
                           "1.7976931348623157e308",
                           "1.7976931348623158e308",
                           "1.7976931348623159e308",
                           "inf",
                           "-inf",
                           "INF",
                           "Infinity",
                           "infinit",
                           "infinityx",
                           "nan",
                           "NaN",
                           "nan(123)",
                           "nan(1_a)",
                           "nan(",
                           "nan(1",
                           "nan(1-)",
                           "-nan",
                           "0x10",
                           "1e",
                           "1e+",
                           "1e-",
                           "e5",
                           ".5",
                           "5.",
                           ".",
                           "-",
                           "-.",
                           "-.5",
                           "1.2.3",
                           "00012",
                           "1E5",
                           "1e05",
                           " 1",
                           "1 ",
                           "",
                           "+1",
                           "--1",
                           "0e999999999999",
                           "-0",
                           "-0.0e-5",
                           "1e-99999999999999999999",
                           "1e99999999999999999999",
                           "0.000e-99999",
                           "0.000000000000000000000000000000000000000000000000001e-300",
                           "123456789012345678901234567890e-400",
                           "9007199254740993",
                           "0.30000000000000004441",
                           "7.2057594037927933e16"}) {
    expectSameRead(text);
  }
  // Many digits: the reading must still round exactly.
  expectSameRead("0." + std::string(800, '0') + "1e800");
  expectSameRead(std::string(400, '9') + ".5");
  expectSameRead("1." + std::string(3000, '0') + "1");
}

TEST(NumberText, ReadMatchesFromCharsOnPrintedDoubles) {
  std::mt19937_64 rng(44);
  std::uniform_int_distribution<int> precision(0, 20);
  char text[512];
  for (const double v : randomValues(45, scaledCount(100000))) {
    expectSameRead(numberText(v));
    const int p = precision(rng);
    std::snprintf(text, sizeof text, "%.*e", p, v);
    expectSameRead(text);
    std::snprintf(text, sizeof text, "%.*g", p, v);
    expectSameRead(text);
    if (std::abs(v) < 1e30) {
      std::snprintf(text, sizeof text, "%.*f", p, v);
      expectSameRead(text);
    }
  }
}

TEST(NumberText, ReadMatchesFromCharsOnRandomTexts) {
  std::mt19937_64 rng(46);
  constexpr std::string_view kAlphabet = "0123456789000..eeE+--nNaAiIfFtyx()_ ";
  std::uniform_int_distribution<std::size_t> letter(0, kAlphabet.size() - 1);
  std::uniform_int_distribution<int> length(0, 14);
  for (int i = 0; i < scaledCount(300000); ++i) {
    std::string text;
    for (int n = length(rng); n > 0; --n) text += kAlphabet[letter(rng)];
    expectSameRead(text);
  }
}

}  // namespace
}  // namespace cardemo
