#include "geometry/trig.hpp"

#include <cmath>
#include <numbers>

namespace cardemo::trig {
namespace {

// The polynomials and the three-part pi/2 are fdlibm's (Sun Microsystems, 1993: k_sin.c, k_cos.c,
// e_rem_pio2.c, s_atan.c), the minimax fits every libm of that lineage carries; the code around
// them is this file's own.

// sin(r) = r + r^3 (S1 + r^2 S2 + ... + r^10 S6) on |r| <= pi/4.
constexpr double kS1 = -1.66666666666666324348e-01;
constexpr double kS2 = 8.33333333332248946124e-03;
constexpr double kS3 = -1.98412698298579493134e-04;
constexpr double kS4 = 2.75573137070700676789e-06;
constexpr double kS5 = -2.50507602534068634195e-08;
constexpr double kS6 = 1.58969099521155010221e-10;

// cos(r) = 1 - r^2/2 + r^4 (C1 + r^2 C2 + ... + r^10 C6) on |r| <= pi/4.
constexpr double kC1 = 4.16666666666666019037e-02;
constexpr double kC2 = -1.38888888888741095749e-03;
constexpr double kC3 = 2.48015872894767294178e-05;
constexpr double kC4 = -2.75573143513906633035e-07;
constexpr double kC5 = 2.08757232129817482790e-09;
constexpr double kC6 = -1.13596475577881948265e-11;

// pi/2 = kHalfPi1 + kHalfPi2 + kHalfPi3 to about 2^-119: the first two have 33 significant bits,
// so k times either is exact for |k| < 2^20.
constexpr double kHalfPi1 = 1.57079632673412561417e+00;
constexpr double kHalfPi2 = 6.07710050630396597660e-11;
constexpr double kHalfPi3 = 2.02226624879595063154e-21;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;
constexpr double kQuarterPi = 0.25 * std::numbers::pi;
// Below this |k| = round(|x| 2/pi) < 2^19 * 0.64 + 1 < 2^20.
constexpr double kMaxReduced = 0x1p19;

// atan(x) = x - x^3 (T0 + x^2 T1 + ... + x^20 T10) on |x| < 7/16.
constexpr double kAtanPoly[11] = {
    3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
    -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
    6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
    -3.65315727442169155270e-02, 1.62858201153657823623e-02};
// atan(0.5), atan(1), atan(1.5) and atan(inf) = pi/2, each as a double and what it leaves.
constexpr double kAtanHigh[4] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                                 9.82793723247329054082e-01, 1.57079632679489655800e+00};
constexpr double kAtanLow[4] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                                1.39033110312309984516e-17, 6.12323399573676603587e-17};
// pi as a double and what it leaves.
constexpr double kPiHigh = std::numbers::pi;
constexpr double kPiLow = 1.2246467991473531772e-16;

// An angle as r = high + low in [-pi/4, pi/4] (about) and the quadrant k mod 4: x = k pi/2 + r.
struct Reduced {
  double high, low;
  int quadrant;
};

// Cody and Waite's reduction (Muller, "Elementary Functions", 3rd ed., ch. 11) with pi/2 in three
// parts. x - k kHalfPi1 is exact (Sterbenz: both lie within a factor two of each other) and so is
// k kHalfPi2; the subtraction of the second part is made exact by TwoSum (Knuth, TAOCP 2,
// 4.2.2), so that an x a few ulps from a multiple of pi/2 keeps its relative accuracy.
Reduced reduce(double x) {
  // Round to nearest, ties to even, without a libm call: |x 2/pi| < 2^51, so adding 1.5 * 2^52
  // leaves no fraction bits, and subtracting it again is exact.
  const double k = (x * kTwoOverPi + 0x1.8p52) - 0x1.8p52;
  const double t = x - k * kHalfPi1;
  const double w = -(k * kHalfPi2);
  const double sum = t + w;
  const double w_part = sum - t;
  const double error = (t - (sum - w_part)) + (w - w_part);
  const double tail = error - k * kHalfPi3;
  const double high = sum + tail;
  const double low = (sum - high) + tail;
  return {high, low, static_cast<int>(k) & 3};
}

// sin(x + y) for |x + y| <= pi/4 (about), y a correction below an ulp of x: sin x + y (1 - x^2/2).
double sinKernel(double x, double y) {
  const double z = x * x;
  const double v = z * x;
  const double p = kS2 + z * (kS3 + z * (kS4 + z * (kS5 + z * kS6)));
  return x - ((z * (0.5 * y - v * p) - y) - v * kS1);
}

// cos(x + y) likewise: cos x - x y. 1 - x^2/2 is formed as w plus what rounding w lost.
double cosKernel(double x, double y) {
  const double z = x * x;
  const double p = z * (kC1 + z * (kC2 + z * (kC3 + z * (kC4 + z * (kC5 + z * kC6)))));
  const double half_z = 0.5 * z;
  const double w = 1.0 - half_z;
  return w + (((1.0 - w) - half_z) + (z * p - x * y));
}

}  // namespace

CosSin cosSin(double radians) {
  if (radians == 0.0) return {1.0, radians};  // keeps the sign of zero
  if (std::abs(radians) <= kQuarterPi) return {cosKernel(radians, 0.0), sinKernel(radians, 0.0)};
  if (!std::isfinite(radians)) return {radians - radians, radians - radians};
  const double x =
      std::abs(radians) <= kMaxReduced ? radians : std::remainder(radians, 2.0 * std::numbers::pi);
  const Reduced r = reduce(x);
  return turnedByQuarters({cosKernel(r.high, r.low), sinKernel(r.high, r.low)}, r.quadrant);
}

CosSin turnedByQuarters(CosSin unit, int quarters) {
  switch (quarters) {
    case 0:
      return unit;
    case 1:
      return {-unit.sin, unit.cos};
    case 2:
      return {-unit.cos, -unit.sin};
    default:
      return {unit.sin, -unit.cos};
  }
}

double tan(double radians) {
  const CosSin cs = cosSin(radians);
  return cs.sin / cs.cos;
}

double atan(double x) {
  if (std::isnan(x)) return x;
  double a = std::abs(x);
  if (a < 0x1p-29) return x;  // atan x = x (1 - x^2/3 + ...) rounds to x
  double result;
  if (a > 0x1p66) {
    result = kAtanHigh[3] + kAtanLow[3];
  } else {
    // Reduced to |t| < 7/16 through atan a = atan c + atan((a - c) / (1 + a c)).
    int id = -1;
    if (a >= 0.4375) {
      if (a < 0.6875) {
        id = 0;
        a = (2.0 * a - 1.0) / (2.0 + a);
      } else if (a < 1.1875) {
        id = 1;
        a = (a - 1.0) / (a + 1.0);
      } else if (a < 2.4375) {
        id = 2;
        a = (a - 1.5) / (1.0 + 1.5 * a);
      } else {
        id = 3;
        a = -1.0 / a;
      }
    }
    const double z = a * a;
    const double w = z * z;
    const double* t = kAtanPoly;
    const double odd = z * (t[0] + w * (t[2] + w * (t[4] + w * (t[6] + w * (t[8] + w * t[10])))));
    const double even = w * (t[1] + w * (t[3] + w * (t[5] + w * (t[7] + w * t[9]))));
    result =
        id < 0 ? a - a * (odd + even) : kAtanHigh[id] - ((a * (odd + even) - kAtanLow[id]) - a);
  }
  return std::copysign(result, x);
}

double atan2(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const double half_pi = kAtanHigh[3] + kAtanLow[3];
  if (y == 0.0) return std::signbit(x) ? std::copysign(kPiHigh, y) : y;
  if (x == 0.0) return std::copysign(half_pi, y);
  if (std::isinf(x)) {
    const double quarter = 0.5 * half_pi;
    if (std::isinf(y)) return std::copysign(x > 0.0 ? quarter : 3.0 * quarter, y);
    return std::copysign(x > 0.0 ? 0.0 : kPiHigh, y);
  }
  if (std::isinf(y)) return std::copysign(half_pi, y);
  const double a = atan(std::abs(y / x));
  return std::copysign(x > 0.0 ? a : kPiHigh - (a - kPiLow), y);
}

}  // namespace cardemo::trig
