#include "geometry/sweep_polygon.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/sweep_intervals.hpp"

namespace cardemo {
namespace {

struct Projection {
  double lo = 0.0;
  double hi = 0.0;
};

template <std::size_t N>
Projection project(const std::array<Eigen::Vector2d, N>& points, int count,
                   const Eigen::Vector2d& axis) {
  Projection r{points[0].dot(axis), points[0].dot(axis)};
  for (int i = 1; i < count; ++i) {
    const double d = points[static_cast<std::size_t>(i)].dot(axis);
    r.lo = std::min(r.lo, d);
    r.hi = std::max(r.hi, d);
  }
  return r;
}

}  // namespace

SweepResult2 sweepObbPolygon(const Obb2& a, const Eigen::Vector2d& displacement,
                             const ConvexPolygon& b) {
  // The candidate axes of collideObbPolygon (A's two axes, B's unnormalised edge normals), with
  // points taken relative to A's centre: the gap at t = 0 is that function's separation to within
  // rounding (it measures two axes at a time from its own reference point).
  const Eigen::Vector2d ex = a.axis * a.half.x();
  const Eigen::Vector2d ey = a.perp() * a.half.y();
  const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
  const std::array<Eigen::Vector2d, 4> box = {zero + ex - ey, zero + ex + ey, zero - ex + ey,
                                              zero - ex - ey};
  std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> poly;
  std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices + 2> axes;
  axes[0] = a.axis;
  axes[1] = a.perp();
  for (int i = 0; i < b.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    poly[k] = b.vertex(i) - a.center;  // subtract in double first (STYLE 8)
    const Eigen::Vector2d e = b.vertex((i + 1) % b.count) - b.vertex(i);
    axes[k + 2] = {e.y(), -e.x()};  // outward for a CCW polygon
  }
  SweepIntervals intervals;
  for (int i = 0; i < b.count + 2; ++i) {
    const Eigen::Vector2d& n = axes[static_cast<std::size_t>(i)];
    const Projection pa = project(box, 4, n);
    const Projection pb = project(poly, b.count, n);
    const double v = n.x() * displacement.x() + n.y() * displacement.y();
    intervals.add(pb.lo - pa.hi, pb.hi - pa.lo, v, n, n.norm());
  }
  return intervals.result();
}

}  // namespace cardemo
