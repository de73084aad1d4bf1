#pragma once
// Bench-local experiment kernels (not product code): the 2D OBB SAT of src/geometry/sat_obb2.cpp
// done at other precisions, to measure what each costs and how often it is wrong. Each answers the
// same query as cardemo::collideObb2 with the same result (hit, separation, unit normal from A
// towards B, the same tie order) and is kept out of line like the product's function, so that
// every kernel does the same work and pays the same call.

#include <cmath>

#include "geometry/obb2.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo::tradeoff {

namespace detail {

// The winning axis: index 0-3 (A's x, y, B's x, y) and the gap along it.
template <typename T>
struct BestAxis {
  int index = 0;
  T gap = T(0);
  bool flip = false;  // the centre offset projects negatively: the normal points the other way
};

// The four gaps from the relative pose, as in sat_obb2.cpp (Gottschalk, Lin and Manocha, "OBBTree",
// 1996): centre offset in A's frame (tx, ty) and in B's frame (tbx, tby), relative rotation
// (c, s). G is the precision of the projections and gaps, T that of the radii.
template <typename G, typename T>
BestAxis<G> bestAxis(G tx, G ty, G tbx, G tby, T c, T s, T hax, T hay, T hbx, T hby) {
  const T ac = std::abs(c), as = std::abs(s);
  const G gaps[4] = {
      std::abs(tx) - static_cast<G>(hax + ac * hbx + as * hby),
      std::abs(ty) - static_cast<G>(hay + as * hbx + ac * hby),
      std::abs(tbx) - static_cast<G>(hbx + ac * hax + as * hay),
      std::abs(tby) - static_cast<G>(hby + as * hax + ac * hay),
  };
  const G along[4] = {tx, ty, tbx, tby};
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (gaps[i] > gaps[best]) best = i;
  }
  return {best, gaps[best], along[best] < G(0)};
}

// The result in the product's form: the winning axis (given in the kernel's precision) as a
// double unit vector signed from A towards B.
template <typename G, typename T>
SatResult2 toResult(const BestAxis<G>& best, T ux, T uy, T vx, T vy) {
  const T axes[4][2] = {{ux, uy}, {-uy, ux}, {vx, vy}, {-vy, vx}};
  Eigen::Vector2d n(static_cast<double>(axes[best.index][0]),
                    static_cast<double>(axes[best.index][1]));
  if (best.flip) n = -n;
  return {best.gap <= G(0), static_cast<double>(best.gap), n};
}

// Everything in T from the centre difference on.
template <typename T>
SatResult2 fromDifference(T dx, T dy, T ux, T uy, T vx, T vy, T hax, T hay, T hbx, T hby) {
  const T tx = ux * dx + uy * dy, ty = ux * dy - uy * dx;
  const T c = ux * vx + uy * vy, s = ux * vy - uy * vx;
  const BestAxis<T> best =
      bestAxis<T, T>(tx, ty, c * tx + s * ty, c * ty - s * tx, c, s, hax, hay, hbx, hby);
  return toResult(best, ux, uy, vx, vy);
}

inline float f(double x) {
  return static_cast<float>(x);
}

}  // namespace detail

/// f32 world coordinates: the centres are converted to float first (as a Box2D user's bodies
/// store them), then everything is float, the centre difference included.
[[gnu::noinline]] inline SatResult2 collideF32World(const Obb2& a, const Obb2& b) {
  using detail::f;
  return detail::fromDifference<float>(f(b.center.x()) - f(a.center.x()),
                                       f(b.center.y()) - f(a.center.y()), f(a.axis.x()),
                                       f(a.axis.y()), f(b.axis.x()), f(b.axis.y()), f(a.half.x()),
                                       f(a.half.y()), f(b.half.x()), f(b.half.y()));
}

/// f32 relative to the query: the centre difference in double, then everything in float.
[[gnu::noinline]] inline SatResult2 collideF32Relative(const Obb2& a, const Obb2& b) {
  using detail::f;
  const Eigen::Vector2d d = b.center - a.center;
  return detail::fromDifference<float>(f(d.x()), f(d.y()), f(a.axis.x()), f(a.axis.y()),
                                       f(b.axis.x()), f(b.axis.y()), f(a.half.x()), f(a.half.y()),
                                       f(b.half.x()), f(b.half.y()));
}

/// f64 throughout, written like the kernels above: the same arithmetic as the product's
/// collideObb2 in the same order, so it separates the cost of precision from that of the code.
[[gnu::noinline]] inline SatResult2 collideF64Kernel(const Obb2& a, const Obb2& b) {
  const Eigen::Vector2d d = b.center - a.center;
  return detail::fromDifference<double>(d.x(), d.y(), a.axis.x(), a.axis.y(), b.axis.x(),
                                        b.axis.y(), a.half.x(), a.half.y(), b.half.x(), b.half.y());
}

/// Mixed: the centre difference and its projections on the four axes in double; the relative
/// rotation and the projected radii in float; each gap (projection minus radius) in double.
[[gnu::noinline]] inline SatResult2 collideMixed(const Obb2& a, const Obb2& b) {
  using detail::f;
  const Eigen::Vector2d d = b.center - a.center;
  const Eigen::Vector2d& u = a.axis;
  const Eigen::Vector2d& v = b.axis;
  const double tx = u.x() * d.x() + u.y() * d.y(), ty = u.x() * d.y() - u.y() * d.x();
  const double tbx = v.x() * d.x() + v.y() * d.y(), tby = v.x() * d.y() - v.y() * d.x();
  const float ux = f(u.x()), uy = f(u.y()), vx = f(v.x()), vy = f(v.y());
  const float c = ux * vx + uy * vy, s = ux * vy - uy * vx;
  const detail::BestAxis<double> best = detail::bestAxis<double, float>(
      tx, ty, tbx, tby, c, s, f(a.half.x()), f(a.half.y()), f(b.half.x()), f(b.half.y()));
  // The normal from the double axes: the projections that chose it were double too.
  return detail::toResult(best, u.x(), u.y(), v.x(), v.y());
}

}  // namespace cardemo::tradeoff
