#pragma once
/// Conversions between doubles and GMP numbers shared by the exact oracles.

#include <gmpxx.h>

#include <cmath>
#include <limits>

namespace cardemo::exact {

/// Precision (bits) of the GMP floats that normalise exact gaps: far beyond a double's 53.
inline constexpr mp_bitcnt_t kFloatBits = 256;

/// The integer X with x = X 2^e exactly; `e` must be at most the exponent of x's lowest set bit.
inline mpz_class scaledInteger(double x, long e) {
  if (x == 0.0) return 0;
  int xe = 0;
  const double frac = std::frexp(x, &xe);
  mpz_class m(std::ldexp(frac, std::numeric_limits<double>::digits));  // exact 53-bit integer
  const long shift = static_cast<long>(xe) - std::numeric_limits<double>::digits - e;
  mpz_mul_2exp(m.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
  return m;
}

/// The double nearest to `x` (mpf_get_d truncates towards zero), compared at x's precision.
inline double nearestDouble(const mpf_class& x) {
  const double t = x.get_d();
  const double away = std::nextafter(t, x >= 0 ? HUGE_VAL : -HUGE_VAL);
  const mpf_class et = abs(x - mpf_class(t, x.get_prec()));
  const mpf_class ea = abs(x - mpf_class(away, x.get_prec()));
  return ea < et ? away : t;
}

}  // namespace cardemo::exact
