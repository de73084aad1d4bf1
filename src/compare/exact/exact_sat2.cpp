#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "compare/exact/dyadic.hpp"
#include "compare/exact/exact_numbers.hpp"
#include "compare/exact/exact_sat.hpp"

namespace cardemo::exact {
namespace {

// Exact dyadic coordinates; 256-bit floats leave the rounded-to-double separation far below a
// nanometre of error.
struct Point {
  Dyadic x, y;
};

// A shape as exact vertices plus its unnormalised edge normals (the candidate axes).
struct Shape {
  std::vector<Point> points;
  std::vector<Point> axes;
};

Point exactPoint(const Eigen::Vector2d& p) {
  return {Dyadic(p.x()), Dyadic(p.y())};
}

Dyadic dot(const Point& a, const Point& b) {
  return a.x * b.x + a.y * b.y;
}

Shape boxShape(const Obb2& box) {
  // Exactly the set of obb2.hpp: centre + a*axis + b*perp(axis), with the double axis taken as is.
  const Point c = exactPoint(box.center);
  const Point u = exactPoint(box.axis);
  const Point v{-u.y, u.x};
  const Dyadic hx(box.half.x()), hy(box.half.y());
  const Point ex{hx * u.x, hx * u.y}, ey{hy * v.x, hy * v.y};
  const auto withSign = [](int sign, const Dyadic& d) { return sign > 0 ? d : -d; };
  Shape s;
  for (const auto& [sx, sy] : {std::pair{1, -1}, {1, 1}, {-1, 1}, {-1, -1}}) {
    s.points.push_back({c.x + withSign(sx, ex.x) + withSign(sy, ey.x),
                        c.y + withSign(sx, ex.y) + withSign(sy, ey.y)});
  }
  s.axes = {u, v};
  return s;
}

Shape polygonShape(const ConvexPolygon& polygon) {
  Shape s;
  for (int i = 0; i < polygon.count; ++i) s.points.push_back(exactPoint(polygon.vertex(i)));
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Point& p = s.points[i];
    const Point& q = s.points[(i + 1) % s.points.size()];
    s.axes.push_back({q.y - p.y, p.x - q.x});
  }
  return s;
}

void project(const Shape& s, const Point& axis, Dyadic& lo, Dyadic& hi) {
  lo = hi = dot(s.points.front(), axis);
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    const Dyadic d = dot(s.points[i], axis);
    if (d < lo) lo = d;
    if (d > hi) hi = d;
  }
}

ExactResult collideShapes(const Shape& a, const Shape& b) {
  bool separated = false;
  bool have_best = false;
  mpf_class best(0, kFloatBits);
  Dyadic alo, ahi, blo, bhi;
  for (const Shape* owner : {&a, &b}) {
    for (const Point& axis : owner->axes) {
      project(a, axis, alo, ahi);
      project(b, axis, blo, bhi);
      const Dyadic forward = blo - ahi;
      const Dyadic backward = alo - bhi;
      const Dyadic& gap = forward > backward ? forward : backward;
      if (gap.sign() > 0) separated = true;
      const Dyadic len2 = dot(axis, axis);
      if (len2.sign() == 0) continue;  // a degenerate axis separates nothing
      mpf_class g = gap.toFloat(kFloatBits);
      g /= sqrt(len2.toFloat(kFloatBits));
      if (!have_best || g > best) {
        best = g;
        have_best = true;
      }
    }
  }
  // Exact SAT decides the hit; the separation is only for reporting.
  return {!separated, have_best ? nearestDouble(best) : 0.0};
}

// Polygons: every coordinate is a double, so all of them are integers times 2^e for the smallest
// exponent e among them. Integer arithmetic (mpz) is then exact and much cheaper than mpq, whose
// every operation reduces a fraction. Gaps scale by 2^(2e) and axis lengths by 2^e.
long lowestBitExponent(double x) {
  if (x == 0.0) return std::numeric_limits<long>::max();
  int e = 0;
  std::frexp(x, &e);
  return static_cast<long>(e) - std::numeric_limits<double>::digits;
}

struct IntPolygon {
  std::vector<mpz_class> x, y;    // vertices
  std::vector<mpz_class> nx, ny;  // unnormalised outward edge normals
};

IntPolygon intPolygon(const ConvexPolygon& p, long e) {
  IntPolygon r;
  for (int i = 0; i < p.count; ++i) {
    r.x.push_back(scaledInteger(p.vertex(i).x(), e));
    r.y.push_back(scaledInteger(p.vertex(i).y(), e));
  }
  for (int i = 0; i < p.count; ++i) {
    const auto j = static_cast<std::size_t>((i + 1) % p.count), k = static_cast<std::size_t>(i);
    r.nx.emplace_back(r.y[j] - r.y[k]);
    r.ny.emplace_back(r.x[k] - r.x[j]);
  }
  return r;
}

void projectInt(const IntPolygon& s, const mpz_class& nx, const mpz_class& ny, mpz_class& lo,
                mpz_class& hi, mpz_class& d) {
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    mpz_mul(d.get_mpz_t(), nx.get_mpz_t(), s.x[i].get_mpz_t());
    mpz_addmul(d.get_mpz_t(), ny.get_mpz_t(), s.y[i].get_mpz_t());
    if (i == 0 || d < lo) lo = d;
    if (i == 0 || d > hi) hi = d;
  }
}

}  // namespace

ExactResult collideObb2(const Obb2& a, const Obb2& b) {
  return collideShapes(boxShape(a), boxShape(b));
}

ExactResult collideObbPolygon(const Obb2& box, const ConvexPolygon& polygon) {
  return collideShapes(boxShape(box), polygonShape(polygon));
}

ExactResult collidePolygons(const ConvexPolygon& a, const ConvexPolygon& b) {
  long e = std::numeric_limits<long>::max();
  for (const ConvexPolygon* p : {&a, &b}) {
    for (int i = 0; i < p->count; ++i) {
      e = std::min({e, lowestBitExponent(p->vertex(i).x()), lowestBitExponent(p->vertex(i).y())});
    }
  }
  if (e == std::numeric_limits<long>::max()) e = 0;  // every coordinate is zero
  const IntPolygon ia = intPolygon(a, e), ib = intPolygon(b, e);
  bool separated = false;
  bool have_best = false;
  mpf_class best(0, kFloatBits), g(0, kFloatBits), len(0, kFloatBits);
  mpz_class alo, ahi, blo, bhi, d, forward, backward, len2;
  for (const IntPolygon* owner : {&ia, &ib}) {
    for (std::size_t k = 0; k < owner->nx.size(); ++k) {
      const mpz_class& nx = owner->nx[k];
      const mpz_class& ny = owner->ny[k];
      projectInt(ia, nx, ny, alo, ahi, d);
      projectInt(ib, nx, ny, blo, bhi, d);
      forward = blo - ahi;
      backward = alo - bhi;
      const mpz_class& gap = forward > backward ? forward : backward;
      if (sgn(gap) > 0) separated = true;
      len2 = nx * nx + ny * ny;
      if (sgn(len2) == 0) continue;
      g = gap;
      len = len2;
      g /= sqrt(len);
      if (!have_best || g > best) {
        best = g;
        have_best = true;
      }
    }
  }
  if (!have_best) return {!separated, 0.0};
  // Undo the integer scaling: gap / |n| carries one factor 2^e.
  if (e >= 0) {
    mpf_mul_2exp(best.get_mpf_t(), best.get_mpf_t(), static_cast<mp_bitcnt_t>(e));
  } else {
    mpf_div_2exp(best.get_mpf_t(), best.get_mpf_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return {!separated, nearestDouble(best)};
}

}  // namespace cardemo::exact
