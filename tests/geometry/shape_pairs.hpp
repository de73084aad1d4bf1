#pragma once
// Random pairs of polygons and boxes for the 2D SAT tests (tests/geometry/convex_polygon_test.cpp
// and the lab's quadrilateral kernels, lab/tests/geometry).

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "random_cases2.hpp"

namespace cardemo::testing {

// One side of a pair: a polygon or a box.
struct Shape {
  bool is_box = false;
  Obb2 box;
  ConvexPolygon poly;

  [[nodiscard]] ConvexPolygon asPolygon() const {
    return is_box ? ConvexPolygon::fromObb(box) : poly;
  }
  [[nodiscard]] std::vector<Eigen::Vector2d> points() const { return pointsOf(asPolygon()); }
  [[nodiscard]] Eigen::Vector2d anchor() const { return is_box ? box.center : poly.vertex(0); }
  void translate(const Eigen::Vector2d& t) {
    if (is_box) {
      box.center += t;
    } else {
      poly = translated(poly, t);
    }
  }
};

inline Shape randomShape(Random& rng, const Eigen::Vector2d& center, double lo, double hi,
                         bool allow_box) {
  Shape s;
  s.is_box = allow_box && rng.integer(0, 2) == 0;
  if (s.is_box) {
    s.box = rng.box(center, lo, hi);
  } else {
    s.poly = rng.polygon(center, lo, hi);
  }
  return s;
}

// Vertex of `p` farthest along `d`.
inline Eigen::Vector2d supportVertex(const ConvexPolygon& p, const Eigen::Vector2d& d) {
  int best = 0;
  for (int i = 1; i < p.count; ++i) {
    if (p.vertex(i).dot(d) > p.vertex(best).dot(d)) best = i;
  }
  return p.vertex(best);
}

// B against one of A's edges (or A against one of B's) at a chosen signed gap along its normal;
// the other shape's nearest vertex lands on that edge, so the gap is usually the SAT separation.
inline std::pair<Shape, Shape> placedNearTouching(Random& rng, Shape a, Shape b) {
  const ConvexPolygon pa = a.asPolygon(), pb = b.asPolygon();
  const bool along_a = rng.integer(0, 1) == 0;
  const ConvexPolygon& owner = along_a ? pa : pb;
  const int k = rng.integer(0, owner.count - 1);
  const Eigen::Vector2d p0 = owner.vertex(k), p1 = owner.vertex((k + 1) % owner.count);
  const Eigen::Vector2d on_edge = p0 + rng.uniform(0.05, 0.95) * (p1 - p0);
  const Eigen::Vector2d m = Eigen::Vector2d((p1 - p0).y(), -(p1 - p0).x()).normalized();
  const Eigen::Vector2d d = along_a ? m : Eigen::Vector2d(-m);  // from A towards B
  const double gap = rng.signedLogUniform(1e-9, 1.0);
  const Eigen::Vector2d meet = along_a ? Eigen::Vector2d(on_edge - supportVertex(pb, -d))
                                       : Eigen::Vector2d(supportVertex(pa, d) - on_edge);
  b.translate(meet + d * gap);
  return {a, b};
}

// A quadrilateral, half the time a box's four corners.
inline Shape randomQuadrilateral(Random& rng, const Eigen::Vector2d& center) {
  Shape s;
  s.poly = rng.integer(0, 1) == 0 ? ConvexPolygon::fromObb(rng.box(center, 0.1, 20.0))
                                  : rng.quadrilateral(center, 0.1, 20.0);
  return s;
}

// Two quadrilaterals (collidePolygons' own fast path) near touching or a few metres apart, up to
// 1e7 m from the origin.
inline std::pair<Shape, Shape> quadrilateralPair(Random& rng) {
  const Eigen::Vector2d base = rng.farPoint(1e7);
  Shape a = randomQuadrilateral(rng, base);
  if (rng.integer(0, 1) == 0) return placedNearTouching(rng, a, randomQuadrilateral(rng, base));
  return {a, randomQuadrilateral(rng, base + rng.offset(0, 20))};
}

// Two squares of side s on an integer grid, the second offset by (dx, dy) with |dx| = |dy| near s,
// so that axes of different directions tie for the largest gap and only the rule "the first slot,
// A's axes before B's" decides the normal. Each square starts at a random corner.
inline std::pair<ConvexPolygon, ConvexPolygon> tiedSquares(Random& rng) {
  const double s = static_cast<double>(rng.integer(1, 3));
  const double d = s + static_cast<double>(rng.integer(-1, 1));
  const Eigen::Vector2d origin(static_cast<double>(rng.integer(-5, 5)) * 1e6, 1e7);
  const Eigen::Vector2d offset(rng.integer(0, 1) == 0 ? d : -d, rng.integer(0, 1) == 0 ? d : -d);
  const auto square = [&rng, s](const Eigen::Vector2d& corner) {
    const Eigen::Vector2d ccw[4] = {{0, 0}, {s, 0}, {s, s}, {0, s}};
    const int first = rng.integer(0, 3);
    ConvexPolygon p;
    p.count = 4;
    for (int k = 0; k < 4; ++k) {
      p.vertices[static_cast<std::size_t>(k)] = corner + ccw[(first + k) % 4];
    }
    return p;
  };
  const ConvexPolygon a = square(origin);
  return {a, square(origin + offset)};
}

}  // namespace cardemo::testing
