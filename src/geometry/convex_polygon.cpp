#include "geometry/convex_polygon.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/finite.hpp"

namespace cardemo {
namespace {

// Turns whose sine is below this are treated as collinear: such a vertex adds nothing to the shape
// and would make an edge normal meaningless.
constexpr double kCollinearSine = 1e-12;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

void explain(std::string* why, std::string text) {
  if (why != nullptr) *why = std::move(text);
}

// Vertices in a frame centred on a reference point, plus the unnormalised SAT axes of the shape.
struct LocalShape {
  std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> points;
  std::array<Eigen::Vector2d, ConvexPolygon::kMaxVertices> axes;
  int point_count = 0;
  int axis_count = 0;
};

LocalShape localPolygon(const ConvexPolygon& p, const Eigen::Vector2d& ref) {
  LocalShape s;
  s.point_count = p.count;
  s.axis_count = p.count;
  for (int i = 0; i < p.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    s.points[k] = p.vertex(i) - ref;
    // Edge from the world coordinates: far from the origin this difference is exact (Sterbenz).
    const Eigen::Vector2d e = p.vertex((i + 1) % p.count) - p.vertex(i);
    s.axes[k] = {e.y(), -e.x()};  // outward for a CCW polygon
  }
  return s;
}

LocalShape localBox(const Obb2& b, const Eigen::Vector2d& ref) {
  LocalShape s;
  const Eigen::Vector2d c = b.center - ref;  // subtract in double first (STYLE 8)
  const Eigen::Vector2d ex = b.axis * b.half.x();
  const Eigen::Vector2d ey = b.perp() * b.half.y();
  s.points[0] = c + ex - ey;
  s.points[1] = c + ex + ey;
  s.points[2] = c - ex + ey;
  s.points[3] = c - ex - ey;
  s.point_count = 4;
  // A box's opposite faces share an axis, so two axes cover its four edge normals.
  s.axes[0] = b.axis;
  s.axes[1] = b.perp();
  s.axis_count = 2;
  return s;
}

struct Interval {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

Interval project(const LocalShape& s, const Eigen::Vector2d& axis) {
  Interval r;
  for (int i = 0; i < s.point_count; ++i) {
    const double d = s.points[static_cast<std::size_t>(i)].dot(axis);
    r.lo = std::min(r.lo, d);
    r.hi = std::max(r.hi, d);
  }
  return r;
}

// Tests the axes of `owner` against both shapes, keeping the largest normalised gap in `best`;
// `finite` turns false when a gap overflowed or an axis length underflowed to zero.
void testAxes(const LocalShape& owner, const LocalShape& a, const LocalShape& b, SatResult2& best,
              bool& first, bool& finite) {
  for (int i = 0; i < owner.axis_count; ++i) {
    const Eigen::Vector2d& n = owner.axes[static_cast<std::size_t>(i)];
    const Interval pa = project(a, n);
    const Interval pb = project(b, n);
    // The gap between the two intervals on this line, whichever side B lies on.
    const double forward = pb.lo - pa.hi;
    const double backward = pa.lo - pb.hi;
    const double length = n.norm();
    const double gap = std::max(forward, backward) / length;
    finite = finite && std::isfinite(gap);
    if (first || gap > best.separation) {
      first = false;
      best.separation = gap;
      best.normal = (forward >= backward ? n : Eigen::Vector2d(-n)) / length;
    }
  }
}

SatResult2 collideScaled(const LocalShape& a, const LocalShape& b, bool& finite) {
  SatResult2 best;
  bool first = true;
  testAxes(a, a, b, best, first, finite);
  testAxes(b, a, b, best, first, finite);
  best.hit = best.separation <= 0.0;
  return best;
}

// The shape scaled by 2^-k (exact, bar underflow below the largest coordinate's 2^-1022), with
// every axis scaled to unit order on its own (a gap divided by its axis length does not depend on
// that length) and zero axes dropped (a zero edge has no normal; fewer axes can only report
// overlap, never a false gap).
LocalShape scaledDown(const LocalShape& s, int k) {
  LocalShape out;
  out.point_count = s.point_count;
  for (int i = 0; i < s.point_count; ++i) {
    const auto j = static_cast<std::size_t>(i);
    out.points[j] = {std::scalbn(s.points[j].x(), -k), std::scalbn(s.points[j].y(), -k)};
  }
  for (int i = 0; i < s.axis_count; ++i) {
    const Eigen::Vector2d& n = s.axes[static_cast<std::size_t>(i)];
    const double m = n.cwiseAbs().maxCoeff();
    if (!(m > 0.0)) continue;
    const int e = std::ilogb(m);
    out.axes[static_cast<std::size_t>(out.axis_count++)] = {std::scalbn(n.x(), -e),
                                                            std::scalbn(n.y(), -e)};
  }
  return out;
}

double largestCoordinate(const LocalShape& s) {
  double m = 0.0;
  for (int i = 0; i < s.point_count; ++i) {
    m = std::max(m, s.points[static_cast<std::size_t>(i)].cwiseAbs().maxCoeff());
  }
  return m;
}

SatResult2 collideLocal(const LocalShape& a, const LocalShape& b) {
  bool finite = true;
  SatResult2 r = collideScaled(a, b, finite);
  if (!finite) {
    // Coordinates beyond ~1e154 square past DBL_MAX in the projections, and edges shorter than
    // ~1e-154 have a zero squared length: the same SAT on the shapes brought to unit order by a
    // power of two, then the separation scaled back (exact in both directions).
    const double largest = std::max(largestCoordinate(a), largestCoordinate(b));
    const int k = largest > 0.0 ? std::ilogb(largest) : 0;
    finite = true;
    r = collideScaled(scaledDown(a, k), scaledDown(b, k), finite);
    r.separation = std::scalbn(r.separation, k);
  }
  assert(isFinite(r));
  return r;
}

}  // namespace

std::optional<ConvexPolygon> ConvexPolygon::fromPoints(std::span<const Eigen::Vector2d> points,
                                                       std::string* why) {
  const int n = static_cast<int>(points.size());
  if (n < 3) {
    explain(why, "a polygon needs at least 3 points, got " + std::to_string(n));
    return std::nullopt;
  }
  if (n > kMaxVertices) {
    explain(why, "a polygon has at most " + std::to_string(kMaxVertices) + " points, got " +
                     std::to_string(n));
    return std::nullopt;
  }
  for (int i = 0; i < n; ++i) {
    if (!points[static_cast<std::size_t>(i)].allFinite()) {
      explain(why, "point " + std::to_string(i) + " is not a finite number");
      return std::nullopt;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (points[static_cast<std::size_t>(i)] == points[static_cast<std::size_t>(j)]) {
        explain(why, "points " + std::to_string(i) + " and " + std::to_string(j) + " are the same");
        return std::nullopt;
      }
    }
  }
  // Work relative to the first point so that polygons far from the origin are judged accurately.
  ConvexPolygon poly;
  poly.count = n;
  const Eigen::Vector2d& ref = points[0];
  double twice_area = 0.0;
  double extent = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p = points[static_cast<std::size_t>(i)] - ref;
    const Eigen::Vector2d q = points[static_cast<std::size_t>((i + 1) % n)] - ref;
    twice_area += cross(p, q);
    extent = std::max(extent, p.norm());
  }
  if (std::abs(twice_area) <= kCollinearSine * extent * extent) {
    explain(why, "the points are collinear (the polygon has no area)");
    return std::nullopt;
  }
  // Store counter-clockwise whatever the input winding.
  for (int i = 0; i < n; ++i) {
    const int src = twice_area > 0.0 ? i : n - 1 - i;
    poly.vertices[static_cast<std::size_t>(i)] = points[static_cast<std::size_t>(src)];
  }
  const auto local = [&](int i) -> Eigen::Vector2d { return poly.vertex((i + n) % n) - ref; };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e0 = local(i) - local(i - 1);
    const Eigen::Vector2d e1 = local(i + 1) - local(i);
    const double turn = cross(e0, e1);
    const double scale = e0.norm() * e1.norm();
    if (std::abs(turn) <= kCollinearSine * scale) {
      explain(why, "point " + std::to_string(twice_area > 0.0 ? i : n - 1 - i) +
                       " is collinear with its neighbours");
      return std::nullopt;
    }
    if (turn < 0.0) {
      explain(why, "the polygon is not convex at point " +
                       std::to_string(twice_area > 0.0 ? i : n - 1 - i));
      return std::nullopt;
    }
  }
  // Every turn is left, but a star (pentagram) turns left everywhere too: strict convexity also
  // needs every other vertex strictly inside each edge's half-plane.
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e = local(i + 1) - local(i);
    for (int k = 0; k < n; ++k) {
      if (k == i || k == (i + 1) % n) continue;
      if (cross(e, local(k) - local(i)) <= 0.0) {
        explain(why,
                "the polygon is not convex: its outline crosses itself or winds more than once");
        return std::nullopt;
      }
    }
  }
  return poly;
}

ConvexPolygon ConvexPolygon::fromObb(const Obb2& box) {
  ConvexPolygon poly;
  const std::array<Eigen::Vector2d, 4> c = box.corners();
  std::copy(c.begin(), c.end(), poly.vertices.begin());
  poly.count = 4;
  return poly;
}

Aabb2 ConvexPolygon::aabb() const {
  Aabb2 box{vertex(0), vertex(0)};
  for (int i = 1; i < count; ++i) {
    box.min = box.min.cwiseMin(vertex(i));
    box.max = box.max.cwiseMax(vertex(i));
  }
  return box;
}

Eigen::Vector2d ConvexPolygon::centroid() const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 1; i < count; ++i) sum += vertex(i) - vertex(0);
  return vertex(0) + sum / static_cast<double>(count);
}

SatResult2 collidePolygons(const ConvexPolygon& a, const ConvexPolygon& b) {
  assert(inDomain(a) && inDomain(b));
  const Eigen::Vector2d& ref = a.vertex(0);
  return collideLocal(localPolygon(a, ref), localPolygon(b, ref));
}

SatResult2 collidePolygonObb(const ConvexPolygon& a, const Obb2& b) {
  assert(inDomain(a) && inDomain(b));
  const Eigen::Vector2d& ref = a.vertex(0);
  return collideLocal(localPolygon(a, ref), localBox(b, ref));
}

SatResult2 collideObbPolygon(const Obb2& a, const ConvexPolygon& b) {
  assert(inDomain(a) && inDomain(b));
  const Eigen::Vector2d& ref = a.center;
  return collideLocal(localBox(a, ref), localPolygon(b, ref));
}

}  // namespace cardemo
