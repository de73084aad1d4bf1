#pragma once
/// Exact dyadic rationals m 2^e for the oracles: every double is one, and sums, differences and
/// products of dyadics are dyadics, so exact arithmetic on doubles needs no fractions. GMP's
/// mpq_class reduces every result by a gcd, which dominates the cost of exact geometry on doubles.

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cardemo::exact {

/// The exact value m 2^e (m an integer of any size, e a binary exponent).
class Dyadic {
 public:
  Dyadic() = default;
  /// The double x, exactly (x must be finite).
  explicit Dyadic(double x) {
    if (x == 0.0) return;
    int xe = 0;
    const double frac = std::frexp(x, &xe);
    m_ = mpz_class(std::ldexp(frac, std::numeric_limits<double>::digits));  // exact 53-bit integer
    e_ = static_cast<long>(xe) - std::numeric_limits<double>::digits;
    // Trailing zero bits dropped: keeps the integers short for doubles like 0.5 or 3.
    const mp_bitcnt_t zeros = mpz_scan1(m_.get_mpz_t(), 0);
    mpz_fdiv_q_2exp(m_.get_mpz_t(), m_.get_mpz_t(), zeros);
    e_ += static_cast<long>(zeros);
  }

  /// -1, 0 or +1.
  [[nodiscard]] int sign() const { return sgn(m_); }

  /// The value rounded (truncated) to a GMP float of `bits` bits of precision.
  [[nodiscard]] mpf_class toFloat(mp_bitcnt_t bits) const {
    mpf_class f(m_, bits);
    if (e_ >= 0) {
      mpf_mul_2exp(f.get_mpf_t(), f.get_mpf_t(), static_cast<mp_bitcnt_t>(e_));
    } else {
      mpf_div_2exp(f.get_mpf_t(), f.get_mpf_t(), static_cast<mp_bitcnt_t>(-e_));
    }
    return f;
  }

  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) { return {a.m_ * b.m_, a.e_ + b.e_}; }
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) { return add(a, b, false); }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return add(a, b, true); }
  friend Dyadic operator-(const Dyadic& a) { return {-a.m_, a.e_}; }
  friend Dyadic abs(const Dyadic& a) { return {abs(a.m_), a.e_}; }
  friend Dyadic& operator+=(Dyadic& a, const Dyadic& b) { return a = a + b; }
  friend bool operator<(const Dyadic& a, const Dyadic& b) { return (a - b).sign() < 0; }
  friend bool operator>(const Dyadic& a, const Dyadic& b) { return b < a; }

 private:
  Dyadic(mpz_class m, long e) : m_(std::move(m)), e_(e) {}

  // a + b or a - b: the operand with the larger exponent is shifted onto the smaller one.
  static Dyadic add(const Dyadic& a, const Dyadic& b, bool subtract) {
    if (sgn(b.m_) == 0) return a;
    if (sgn(a.m_) == 0) return subtract ? -b : b;
    if (a.e_ == b.e_) return {subtract ? mpz_class(a.m_ - b.m_) : mpz_class(a.m_ + b.m_), a.e_};
    const bool a_higher = a.e_ > b.e_;
    const Dyadic& high = a_higher ? a : b;
    const Dyadic& low = a_higher ? b : a;
    const mpz_class shifted = high.m_ << static_cast<mp_bitcnt_t>(high.e_ - low.e_);
    if (!subtract) return {shifted + low.m_, low.e_};
    return {a_higher ? mpz_class(shifted - low.m_) : mpz_class(low.m_ - shifted), low.e_};
  }

  mpz_class m_;
  long e_ = 0;
};

}  // namespace cardemo::exact
