#include "compare/exact/exact_sweep.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "compare/exact/exact_numbers.hpp"

namespace cardemo::exact {
namespace {

// Every input is a double, so every input is an integer times 2^e for the smallest exponent e
// among them (e <= 0 here). Working in those integers (mpz) is exact and far cheaper than mpq,
// which reduces a fraction at every step (the same idea as collidePolygons in exact_sat2.cpp).
// Quantities then carry a "degree": a coordinate is degree 1 (real = X 2^e), a projection on an
// edge-normal axis degree 2, a box radius h |u . n| degree 3; all interval ends are lifted to
// degree 3, and a time p / v (degree 3 over degree 2) is T 2^e.
long commonExponent(double x) {
  if (x == 0.0) return 0;
  int e = 0;
  std::frexp(x, &e);
  return std::min(0L, static_cast<long>(e) - std::numeric_limits<double>::digits);
}

struct IntVec {
  mpz_class x, y;
};

struct IntBox {
  IntVec c, u;       // centre and unit axis as stored (degree 1)
  mpz_class hx, hy;  // half extents (degree 1)
};

IntBox intBox(const Obb2& b, long e) {
  return {{scaledInteger(b.center.x(), e), scaledInteger(b.center.y(), e)},
          {scaledInteger(b.axis.x(), e), scaledInteger(b.axis.y(), e)},
          scaledInteger(b.half.x(), e),
          scaledInteger(b.half.y(), e)};
}

// A closed interval of t as fractions num / den (den > 0), in units of 2^e; flags for infinity.
struct Fraction {
  mpz_class num, den;
};

bool less(const Fraction& a, const Fraction& b) {
  return a.num * b.den < b.num * a.den;
}

class Sweep {
 public:
  Sweep(long e, double inflate) : e_(e), inflate_(inflate) {
    // t = 1 is T = 2^-e.
    mpz_ui_pow_ui(one_.get_mpz_t(), 2, static_cast<unsigned long>(-e));
  }

  // Projections of A at t = 0 and of B on axis n (degree 1), lifted to degree 3; v = n . d
  // (degree 2).
  void add(const IntVec& n, mpz_class alo, mpz_class ahi, const mpz_class& blo,
           const mpz_class& bhi, const mpz_class& v) {
    if (inflate_ != 0.0) {
      // Widen A's projection by inflate |n|: |n| = |N| 2^e, in degree-3 units inflate |N| 2^-2e.
      mpf_class len(n.x * n.x + n.y * n.y, kFloatBits);
      len = sqrt(len) * inflate_;
      mpf_mul_2exp(len.get_mpf_t(), len.get_mpf_t(), static_cast<mp_bitcnt_t>(-2 * e_));
      const mpz_class m(len);
      alo -= m;
      ahi += m;
    }
    const mpz_class p = blo - ahi, q = bhi - alo;
    // Static gap at t = 0, for the normal when the shapes already touch.
    const mpz_class& gap = p >= -q ? p : mpz_class(-q);
    mpf_class g(gap, kFloatBits);
    g /= sqrt(mpf_class(n.x * n.x + n.y * n.y, kFloatBits));
    if (!have_start_ || g > start_gap_) {
      have_start_ = true;
      start_gap_ = g;
      start_axis_ = n;
      start_sign_ = p >= -q ? 1 : -1;
    }
    const int sv = sgn(v);
    if (sv == 0) {
      if (sgn(p) > 0 || sgn(q) < 0) empty_ = true;
      return;
    }
    Fraction enter{sv > 0 ? p : mpz_class(-q), sv > 0 ? v : mpz_class(-v)};
    Fraction leave{sv > 0 ? q : mpz_class(-p), sv > 0 ? v : mpz_class(-v)};
    if (!have_enter_ || less(enter_, enter)) {
      have_enter_ = true;
      enter_ = enter;
      enter_axis_ = n;
      enter_sign_ = sv;
      enter_v_ = v;
    }
    if (!have_leave_ || less(leave, leave_)) {
      have_leave_ = true;
      leave_ = leave;
    }
  }

  [[nodiscard]] ExactSweep result() const {
    ExactSweep r;
    if (empty_) return r;
    const Fraction zero{0, 1}, one{one_, 1};
    if (have_enter_ && have_leave_ && less(leave_, enter_)) return r;
    if (have_enter_ && less(one, enter_)) return r;
    if (have_leave_ && less(leave_, zero)) return r;
    r.hit = true;
    if (have_enter_ && less(zero, enter_)) {
      mpf_class t(enter_.num, kFloatBits);
      t /= mpf_class(enter_.den, kFloatBits);
      mpf_div_2exp(t.get_mpf_t(), t.get_mpf_t(), static_cast<mp_bitcnt_t>(-e_));
      r.toi = nearestDouble(t);
      r.normal = unit(enter_axis_, enter_sign_);
      mpf_class len(enter_axis_.x * enter_axis_.x + enter_axis_.y * enter_axis_.y, kFloatBits);
      mpf_class c(abs(enter_v_), kFloatBits);
      c /= sqrt(len);
      // closing = |V| / |N| 2^e.
      mpf_div_2exp(c.get_mpf_t(), c.get_mpf_t(), static_cast<mp_bitcnt_t>(-e_));
      r.closing = nearestDouble(c);
    } else {
      r.toi = 0.0;
      r.normal = unit(start_axis_, start_sign_);
    }
    return r;
  }

 private:
  long e_;
  double inflate_;
  mpz_class one_;
  bool empty_ = false;
  bool have_enter_ = false, have_leave_ = false, have_start_ = false;
  Fraction enter_, leave_;
  IntVec enter_axis_, start_axis_;
  int enter_sign_ = 1, start_sign_ = 1;
  mpz_class enter_v_;
  mpf_class start_gap_{0, kFloatBits};

  // Nearest double to x (mpf_get_d truncates towards zero).
  static Eigen::Vector2d unit(const IntVec& n, int sign) {
    mpf_class len(n.x * n.x + n.y * n.y, kFloatBits);
    len = sqrt(len);
    const mpf_class x = mpf_class(n.x, kFloatBits) / len, y = mpf_class(n.y, kFloatBits) / len;
    return {sign * nearestDouble(x), sign * nearestDouble(y)};
  }
};

mpz_class dot(const IntVec& a, const IntVec& b) {
  return a.x * b.x + a.y * b.y;
}

// Box projection on axis n, lifted to degree 3: centre (degree 2) shifted up by -e bits, radius
// h |u . n| + h |perp(u) . n| (degree 3).
void projectBox(const IntBox& b, const IntVec& n, long e, mpz_class& lo, mpz_class& hi) {
  mpz_class centre = dot(b.c, n);
  mpz_mul_2exp(centre.get_mpz_t(), centre.get_mpz_t(), static_cast<mp_bitcnt_t>(-e));
  const IntVec perp{-b.u.y, b.u.x};
  const mpz_class r = b.hx * abs(dot(b.u, n)) + b.hy * abs(dot(perp, n));
  lo = centre - r;
  hi = centre + r;
}

long exponentOf(std::initializer_list<double> values, long e) {
  for (const double v : values) e = std::min(e, commonExponent(v));
  return e;
}

long boxExponent(const Obb2& b, long e) {
  return exponentOf({b.center.x(), b.center.y(), b.axis.x(), b.axis.y(), b.half.x(), b.half.y()},
                    e);
}

}  // namespace

ExactSweep sweepObb2(const Obb2& a, const Eigen::Vector2d& displacement, const Obb2& b,
                     double inflate) {
  long e = boxExponent(a, boxExponent(b, 0));
  e = exponentOf({displacement.x(), displacement.y()}, e);
  const IntBox ia = intBox(a, e), ib = intBox(b, e);
  const IntVec d{scaledInteger(displacement.x(), e), scaledInteger(displacement.y(), e)};
  Sweep sweep(e, inflate);
  mpz_class alo, ahi, blo, bhi;
  for (const IntVec& n : {ia.u, IntVec{-ia.u.y, ia.u.x}, ib.u, IntVec{-ib.u.y, ib.u.x}}) {
    projectBox(ia, n, e, alo, ahi);
    projectBox(ib, n, e, blo, bhi);
    sweep.add(n, alo, ahi, blo, bhi, dot(n, d));
  }
  return sweep.result();
}

ExactSweep sweepObbPolygon(const Obb2& a, const Eigen::Vector2d& displacement,
                           const ConvexPolygon& b, double inflate) {
  long e = boxExponent(a, 0);
  e = exponentOf({displacement.x(), displacement.y()}, e);
  for (int i = 0; i < b.count; ++i) e = exponentOf({b.vertex(i).x(), b.vertex(i).y()}, e);
  const IntBox ia = intBox(a, e);
  const IntVec d{scaledInteger(displacement.x(), e), scaledInteger(displacement.y(), e)};
  std::vector<IntVec> vertices;
  vertices.reserve(static_cast<std::size_t>(b.count));
  for (int i = 0; i < b.count; ++i) {
    vertices.push_back({scaledInteger(b.vertex(i).x(), e), scaledInteger(b.vertex(i).y(), e)});
  }
  std::vector<IntVec> axes{ia.u, IntVec{-ia.u.y, ia.u.x}};
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const IntVec& p = vertices[i];
    const IntVec& q = vertices[(i + 1) % vertices.size()];
    axes.push_back({q.y - p.y, p.x - q.x});  // outward for a CCW polygon
  }
  Sweep sweep(e, inflate);
  mpz_class alo, ahi, blo, bhi, proj;
  for (const IntVec& n : axes) {
    projectBox(ia, n, e, alo, ahi);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      proj = dot(vertices[i], n);
      if (i == 0 || proj < blo) blo = proj;
      if (i == 0 || proj > bhi) bhi = proj;
    }
    mpz_mul_2exp(blo.get_mpz_t(), blo.get_mpz_t(), static_cast<mp_bitcnt_t>(-e));
    mpz_mul_2exp(bhi.get_mpz_t(), bhi.get_mpz_t(), static_cast<mp_bitcnt_t>(-e));
    sweep.add(n, alo, ahi, blo, bhi, dot(n, d));
  }
  return sweep.result();
}

}  // namespace cardemo::exact
