#include "geometry/convex_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

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

}  // namespace cardemo
