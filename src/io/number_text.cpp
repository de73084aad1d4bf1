#include "io/number_text.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>

#include "geometry/bit_cast.hpp"

// snprintf and strtod follow LC_NUMERIC; cardemo never calls setlocale, so they run in the "C"
// locale, with '.' as the decimal point, as std::to_chars and std::from_chars always do.

namespace cardemo {
namespace {

// 17 significant digits tell every double apart.
constexpr int kMaxDigits = 17;

// digits * 10^(exponent - count + 1): `count` significant digits, the first one not zero, and
// `exponent` the power of ten of the first one (scientific notation's exponent).
struct Decimal {
  std::uint64_t digits = 0;
  int count = 0;
  int exponent = 0;
};

// A double's first 17 significant digits, rounded exactly (printf: ties to even), as characters.
struct Digits17 {
  char digit[kMaxDigits];
  int exponent = 0;
};

std::uint64_t powerOfTen(int n) {
  std::uint64_t p = 1;
  for (int i = 0; i < n; ++i) p *= 10;
  return p;
}

// printf's "%.*e" text of `magnitude` (finite, > 0) with `count` digits, as a Decimal.
Decimal printedDecimal(double magnitude, int count, char* digits_out = nullptr) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*e", count - 1, magnitude);
  Decimal d;
  d.count = count;
  int n = 0;
  const char* c = text;
  for (; *c != 'e'; ++c) {
    if (*c == '.') continue;
    if (digits_out != nullptr) digits_out[n++] = *c;
    d.digits = d.digits * 10 + static_cast<std::uint64_t>(*c - '0');
  }
  d.exponent = std::atoi(c + 1);
  return d;
}

// The next decimal of the same digit count up (+1) or down (-1).
Decimal neighbour(Decimal d, int direction) {
  const std::uint64_t lowest = powerOfTen(d.count - 1);
  if (direction > 0) {
    d.digits += 1;
    if (d.digits == lowest * 10) {
      d.digits = lowest;
      d.exponent += 1;
    }
  } else {
    d.digits -= 1;
    if (d.digits < lowest) {
      d.digits = lowest * 10 - 1;
      d.exponent -= 1;
    }
  }
  return d;
}

// `magnitude` rounded exactly to `count` (< 17) digits, from its 17 digits `all`. Rounding those
// again is exact unless the digits dropped read 50...0 (the first rounding may have made that
// tie): then printf rounds `magnitude` itself.
Decimal roundedTo(double magnitude, const Digits17& all, int count) {
  bool tail_zero = true;
  for (int i = count + 1; i < kMaxDigits; ++i) tail_zero &= all.digit[i] == '0';
  const char next = all.digit[count];
  if (next == '5' && tail_zero) return printedDecimal(magnitude, count);
  Decimal d{0, count, all.exponent};
  for (int i = 0; i < count; ++i)
    d.digits = d.digits * 10 + static_cast<std::uint64_t>(all.digit[i] - '0');
  return next >= '5' ? neighbour(d, 1) : d;
}

// The double that the decimal reads back as (strtod rounds exactly, ties to even).
double valueOf(const Decimal& d) {
  char text[40];
  char* end = std::to_chars(text, text + sizeof text - 1, d.digits).ptr;
  *end++ = 'e';
  end = std::to_chars(end, text + sizeof text - 1, d.exponent - d.count + 1).ptr;
  *end = '\0';
  return std::strtod(text, nullptr);
}

__extension__ using Wide = unsigned __int128;

// 5^k for k <= kMaxFive: with at most 17 digits (< 2^57) times 5^27 (< 2^63), under 2^120.
constexpr int kMaxFive = 27;
constexpr auto kPowersOfFive = [] {
  std::array<std::uint64_t, kMaxFive + 1> p{};
  p[0] = 1;
  for (int k = 1; k <= kMaxFive; ++k)
    p[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(k - 1)] * 5;
  return p;
}();

int bitWidth(Wide v) {
  const auto high = static_cast<std::uint64_t>(v >> 64);
  const auto low = static_cast<std::uint64_t>(v);
  if (high != 0) return 128 - __builtin_clzll(high);
  return low != 0 ? 64 - __builtin_clzll(low) : 0;
}

// The sign of d - n * 2^t, exactly: both sides as integers times powers of 5 and 2 (10^q is
// 5^q 2^q), moved to the side where the powers are positive; nullopt when that needs more than
// 128 bits (magnitudes outside about 1e-10..1e27), left to strtod.
std::optional<int> compareExactly(const Decimal& d, std::uint64_t n, int t) {
  const int q = d.exponent - d.count + 1;
  const int five_left = std::max(q, 0);
  const int five_right = std::max(-q, 0);
  if (five_left > kMaxFive || five_right > kMaxFive) return std::nullopt;
  Wide left = Wide{d.digits} * kPowersOfFive[static_cast<std::size_t>(five_left)];
  Wide right = Wide{n} * kPowersOfFive[static_cast<std::size_t>(five_right)];
  const int shift = q - t;  // 2^q on the left against 2^t on the right
  Wide& shifted = shift > 0 ? left : right;
  const int by = std::abs(shift);
  if (by > 0) {
    if (bitWidth(shifted) + by > 127) return std::nullopt;
    shifted <<= by;
  }
  return left < right ? -1 : (left > right ? 1 : 0);
}

// Where a decimal falls against a double: below the values that round to it, among them, above.
enum class Side { kBelow, kOn, kAbove };

// Side of `d` against `magnitude` (finite, > 0) as strtod would round `d`: exact integer arithmetic
// where 128 bits suffice (strtod is slow, in the browser build above all), strtod itself elsewhere.
Side sideOf(const Decimal& d, double magnitude) {
  const auto bits = bitCast<std::uint64_t>(magnitude);
  const int biased = static_cast<int>(bits >> 52);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const int e = biased == 0 ? -1074 : biased - 1075;  // magnitude = m * 2^e
  // In units of 2^(e-2) the double is 4m, and the values that round to it reach 2 units up and 2
  // down, or 1 down at a power of two (its lower neighbour is half as far); the ends round to it
  // when m is even (ties to even).
  const bool even = (m & 1) == 0;
  const std::uint64_t lower = 4 * m - (fraction == 0 && biased > 1 ? 1 : 2);
  const std::uint64_t upper = 4 * m + 2;
  const std::optional<int> low = compareExactly(d, lower, e - 2);
  const std::optional<int> high = compareExactly(d, upper, e - 2);
  if (!low || !high) {
    const double back = valueOf(d);
    return back == magnitude ? Side::kOn : (back < magnitude ? Side::kBelow : Side::kAbove);
  }
  if (*low < 0 || (*low == 0 && !even)) return Side::kBelow;
  if (*high > 0 || (*high == 0 && !even)) return Side::kAbove;
  return Side::kOn;
}

// A decimal of `count` digits that reads back as `magnitude`, the nearest one when there are two;
// digits == 0 when there is none. Only the two decimals on either side of `magnitude` can qualify:
// the nearest, or, when it reads back wrong, the one on the other side (the rounding interval of
// a power of two is wider above it than below).
Decimal readsBackWith(double magnitude, const Digits17& all, int count) {
  const Decimal nearest = roundedTo(magnitude, all, count);
  const Side side = sideOf(nearest, magnitude);
  if (side == Side::kOn) return nearest;
  const Decimal other = neighbour(nearest, side == Side::kBelow ? 1 : -1);
  return sideOf(other, magnitude) == Side::kOn ? other : Decimal{};
}

// The fewest significant digits that read back as `magnitude` (finite, > 0). Whether some decimal
// of n digits reads back is monotone in n (one of n digits is one of n + 1 with a trailing zero).
// Most doubles need 16 or 17 digits, so those two counts are tried first, then the rest bisected.
Decimal shortestDecimal(double magnitude) {
  Digits17 all;
  const Decimal full = printedDecimal(magnitude, kMaxDigits, all.digit);
  all.exponent = full.exponent;
  Decimal best = full;
  int high = kMaxDigits;  // the fewest digits known to read back
  for (const int count : {kMaxDigits - 1, kMaxDigits - 2}) {
    const Decimal d = readsBackWith(magnitude, all, count);
    if (d.count == 0) return best;
    best = d;
    high = count;
  }
  int low = 1;
  while (low < high) {
    const int middle = (low + high) / 2;
    const Decimal d = readsBackWith(magnitude, all, middle);
    if (d.count != 0) {
      best = d;
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  assert(best.count == low);
  return best;
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// True when `text` starts with `word` (lower case), in any case.
bool startsWithWord(std::string_view text, std::string_view word) {
  if (text.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char c =
        text[i] >= 'A' && text[i] <= 'Z' ? static_cast<char>(text[i] - 'A' + 'a') : text[i];
    if (c != word[i]) return false;
  }
  return true;
}

// Length of "nan" or "nan(chars)" at the start of `text`, chars letters, digits and '_'.
std::size_t nanLength(std::string_view text) {
  std::size_t at = 3;
  if (at >= text.size() || text[at] != '(') return 3;
  for (++at; at < text.size(); ++at) {
    const char c = text[at];
    if (c == ')') return at + 1;
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!letter && !isDigit(c) && c != '_') return 3;
  }
  return 3;
}

std::string nonFiniteText(double value) {
  if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
  return value < 0 ? "-inf" : "inf";
}

std::string scientificText(const Decimal& d) {
  const std::string digits = std::to_string(d.digits);
  std::string out(1, digits[0]);
  if (d.count > 1) out += '.' + digits.substr(1);
  out += d.exponent < 0 ? "e-" : "e+";
  const int magnitude = std::abs(d.exponent);
  if (magnitude < 10) out += '0';
  out += std::to_string(magnitude);
  return out;
}

// Fixed notation of the shortest decimal `d` of `magnitude`.
std::string fixedShortestText(double magnitude, const Decimal& d) {
  const std::string digits = std::to_string(d.digits);
  if (d.exponent >= d.count - 1) {
    // An integer. Past the significant digits std::to_chars writes the exact value's digits (of
    // several texts of the same length it takes the nearest), as printf's %.0f does.
    if (d.exponent == d.count - 1) return digits;
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", magnitude);
    return text;
  }
  if (d.exponent >= 0) {
    const auto point = static_cast<std::size_t>(d.exponent + 1);
    return digits.substr(0, point) + '.' + digits.substr(point);
  }
  return "0." + std::string(static_cast<std::size_t>(-d.exponent - 1), '0') + digits;
}

}  // namespace

std::string numberText(double value) {
  if (!std::isfinite(value)) return nonFiniteText(value);
  const std::string sign = std::signbit(value) ? "-" : "";
  if (value == 0.0) return sign + "0";
  const double magnitude = std::abs(value);
  const Decimal d = shortestDecimal(magnitude);
  // Lengths without the sign; scientific has "e+" and at least two exponent digits.
  const int exponent_digits = std::abs(d.exponent) >= 100 ? 3 : 2;
  const int scientific = d.count + (d.count > 1 ? 1 : 0) + 2 + exponent_digits;
  int fixed = 0;
  if (d.exponent < 0) {
    fixed = 2 + (-d.exponent - 1) + d.count;  // "0.", zeros, digits
  } else {
    fixed = d.count <= d.exponent + 1 ? d.exponent + 1 : d.count + 1;
  }
  return sign + (fixed <= scientific ? fixedShortestText(magnitude, d) : scientificText(d));
}

std::string fixedText(double value, int decimals) {
  assert(decimals >= 0);
  if (!std::isfinite(value)) return nonFiniteText(value);
  const int size = std::snprintf(nullptr, 0, "%.*f", decimals, value);
  std::string out(static_cast<std::size_t>(size) + 1, '\0');
  std::snprintf(out.data(), out.size(), "%.*f", decimals, value);
  out.pop_back();
  return out;
}

NumberRead readNumber(std::string_view text, double& value) {
  std::size_t at = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) at = 1;
  const std::string_view rest = text.substr(at);
  if (startsWithWord(rest, "inf")) {
    value = negative ? -std::numeric_limits<double>::infinity()
                     : std::numeric_limits<double>::infinity();
    return {at + (startsWithWord(rest, "infinity") ? 8u : 3u), {}};
  }
  if (startsWithWord(rest, "nan")) {
    value = negative ? -std::numeric_limits<double>::quiet_NaN()
                     : std::numeric_limits<double>::quiet_NaN();
    return {at + nanLength(rest), {}};
  }
  // Digits with at most one point, at least one digit; then an exponent if it has digits.
  bool nonzero = false;
  std::size_t digits = 0;
  const auto scanDigits = [&] {
    for (; at < text.size() && isDigit(text[at]); ++at, ++digits) nonzero |= text[at] != '0';
  };
  scanDigits();
  if (at < text.size() && text[at] == '.') {
    ++at;
    scanDigits();
  }
  if (digits == 0) return {0, std::errc::invalid_argument};
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    std::size_t e = at + 1;
    if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
    if (e < text.size() && isDigit(text[e])) {
      at = e;
      while (at < text.size() && isDigit(text[at])) ++at;
    }
  }
  const std::string number(text.substr(0, at));
  const double read = std::strtod(number.c_str(), nullptr);
  if (std::isinf(read) || (read == 0.0 && nonzero)) return {at, std::errc::result_out_of_range};
  value = read;
  return {at, {}};
}

}  // namespace cardemo
