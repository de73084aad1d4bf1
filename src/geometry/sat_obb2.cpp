#include "geometry/sat_obb2.hpp"

#include <cassert>
#include <cmath>

#include "geometry/finite.hpp"

namespace cardemo {
namespace {

// The pair in A's frame: B's centre and B's axes expressed in A's local coordinates.
struct RelativePose2 {
  Eigen::Vector2d t;  // B's centre minus A's centre, in A's frame
  double c = 1.0;     // cos of B's heading relative to A
  double s = 0.0;     // sin of B's heading relative to A
};

// Always inlined: out of line (GCC 12 -O2 keeps one copy for its two callers) the 32-byte result
// goes through memory and collideObb2 took twice as long, 20 ns instead of 10 ns per pair
// (bench/tradeoff/precision.cpp; docs/performance.md, "Run time against error").
[[gnu::always_inline]] inline RelativePose2 relativePose(const Obb2& a, const Obb2& b) {
  // Subtract in double first (STYLE 8): the difference is small even when both centres are 1e7 m
  // out.
  const Eigen::Vector2d d = b.center - a.center;
  const Eigen::Vector2d& u = a.axis;
  return {{u.x() * d.x() + u.y() * d.y(), u.x() * d.y() - u.y() * d.x()},
          u.x() * b.axis.x() + u.y() * b.axis.y(),
          u.x() * b.axis.y() - u.y() * b.axis.x()};
}

}  // namespace

bool overlapObb2(const Obb2& a, const Obb2& b) {
  assert(inDomain(a) && inDomain(b));
  const RelativePose2 p = relativePose(a, b);
  const double ac = std::abs(p.c), as = std::abs(p.s);
  // A's axes: B's projected radius is |R| * hB (Gottschalk et al., OBBTree, 1996).
  if (std::abs(p.t.x()) > a.half.x() + ac * b.half.x() + as * b.half.y()) return false;
  if (std::abs(p.t.y()) > a.half.y() + as * b.half.x() + ac * b.half.y()) return false;
  // B's axes, with t rotated into B's frame.
  const double tbx = p.c * p.t.x() + p.s * p.t.y();
  const double tby = p.c * p.t.y() - p.s * p.t.x();
  if (std::abs(tbx) > b.half.x() + ac * a.half.x() + as * a.half.y()) return false;
  if (std::abs(tby) > b.half.y() + as * a.half.x() + ac * a.half.y()) return false;
  return true;
}

SatResult2 collideObb2(const Obb2& a, const Obb2& b) {
  assert(inDomain(a) && inDomain(b));
  const RelativePose2 p = relativePose(a, b);
  const double ac = std::abs(p.c), as = std::abs(p.s);
  const double tbx = p.c * p.t.x() + p.s * p.t.y();
  const double tby = p.c * p.t.y() - p.s * p.t.x();
  const double gaps[4] = {
      std::abs(p.t.x()) - (a.half.x() + ac * b.half.x() + as * b.half.y()),
      std::abs(p.t.y()) - (a.half.y() + as * b.half.x() + ac * b.half.y()),
      std::abs(tbx) - (b.half.x() + ac * a.half.x() + as * a.half.y()),
      std::abs(tby) - (b.half.y() + as * a.half.x() + ac * a.half.y()),
  };
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (gaps[i] > gaps[best]) best = i;
  }
  // Axis in world coordinates, signed so that it points from A towards B.
  const Eigen::Vector2d axes[4] = {a.axis, a.perp(), b.axis, b.perp()};
  const double along[4] = {p.t.x(), p.t.y(), tbx, tby};
  const Eigen::Vector2d normal = along[best] < 0.0 ? Eigen::Vector2d(-axes[best]) : axes[best];
  SatResult2 r{gaps[best] <= 0.0, gaps[best], normal};
  assert(isFinite(r));
  return r;
}

}  // namespace cardemo
