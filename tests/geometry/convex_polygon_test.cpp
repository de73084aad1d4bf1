#include "geometry/convex_polygon.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "geometry/sat_obb2.hpp"
#include "random_cases2.hpp"
#include "shape_pairs.hpp"

namespace cardemo {
namespace {

using testing::ClassStats;
using testing::Failures;
using testing::placedNearTouching;
using testing::quadrilateralPair;
using testing::Random;
using testing::randomShape;
using testing::Shape;

// --- fromPoints -------------------------------------------------------------------------------

std::optional<ConvexPolygon> build(std::vector<Eigen::Vector2d> points, std::string* why) {
  return ConvexPolygon::fromPoints(points, why);
}

void expectRejected(std::vector<Eigen::Vector2d> points, const std::string& word) {
  std::string why;
  EXPECT_FALSE(build(points, &why).has_value());
  EXPECT_NE(why.find(word), std::string::npos) << "why = \"" << why << "\"";
}

TEST(ConvexPolygonFromPoints, RejectsCollinearPoints) {
  expectRejected({{0, 0}, {1, 1}, {2, 2}}, "collinear");
  expectRejected({{1e7, 1e7}, {1e7 + 1, 1e7}, {1e7 + 3, 1e7}, {1e7 + 2, 1e7}}, "collinear");
}

TEST(ConvexPolygonFromPoints, RejectsCollinearMiddleVertex) {
  expectRejected({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, "collinear");
}

TEST(ConvexPolygonFromPoints, RejectsDuplicatePoints) {
  expectRejected({{0, 0}, {1, 0}, {1, 1}, {1, 0}}, "same");
  expectRejected({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, "same");
}

TEST(ConvexPolygonFromPoints, RejectsNonConvex) {
  expectRejected({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}}, "not convex");
}

TEST(ConvexPolygonFromPoints, RejectsSelfIntersectingStar) {
  // A pentagram turns the same way at every vertex but winds twice.
  std::vector<Eigen::Vector2d> star;
  for (int i = 0; i < 5; ++i) {
    const double t = 2.0 * std::numbers::pi * (2 * i % 5) / 5.0;
    star.push_back({std::cos(t), std::sin(t)});
  }
  expectRejected(star, "not convex");
}

TEST(ConvexPolygonFromPoints, RejectsTooFewPoints) {
  expectRejected({{0, 0}, {1, 0}}, "at least 3");
  expectRejected({}, "at least 3");
}

TEST(ConvexPolygonFromPoints, RejectsTooManyPoints) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 17; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 17.0;
    points.push_back({std::cos(t), std::sin(t)});
  }
  expectRejected(points, "at most 16");
  points.pop_back();
  EXPECT_TRUE(build(points, nullptr).has_value()) << "16 points on a circle are fine";
}

TEST(ConvexPolygonFromPoints, RejectsNaN) {
  expectRejected({{0, 0}, {1, std::numeric_limits<double>::quiet_NaN()}, {0, 1}}, "finite");
  expectRejected({{0, 0}, {1, 0}, {std::numeric_limits<double>::infinity(), 1}}, "finite");
}

TEST(ConvexPolygonFromPoints, ClockwiseInputIsStoredCounterClockwise) {
  const std::vector<Eigen::Vector2d> cw{{0, 0}, {0, 2}, {3, 2}, {3, 0}};
  const auto p = build(cw, nullptr);
  ASSERT_TRUE(p.has_value());
  ASSERT_EQ(p->count, 4);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d e0 = p->vertex((i + 1) % 4) - p->vertex(i);
    const Eigen::Vector2d e1 = p->vertex((i + 2) % 4) - p->vertex((i + 1) % 4);
    EXPECT_GT(e0.x() * e1.y() - e0.y() * e1.x(), 0.0) << "turn " << i;
  }
  // Same point set.
  for (const Eigen::Vector2d& q : cw) {
    EXPECT_NE(std::find(p->vertices.begin(), p->vertices.begin() + 4, q), p->vertices.begin() + 4);
  }
}

TEST(ConvexPolygonFromPoints, CounterClockwiseInputKeepsItsOrder) {
  const std::vector<Eigen::Vector2d> ccw{{1e7, 1e7}, {1e7 + 3, 1e7}, {1e7 + 3, 1e7 + 2}};
  const auto p = build(ccw, nullptr);
  ASSERT_TRUE(p.has_value());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(p->vertex(i), ccw[static_cast<std::size_t>(i)]);
  EXPECT_EQ(p->aabb().min, Eigen::Vector2d(1e7, 1e7));
  EXPECT_EQ(p->aabb().max, Eigen::Vector2d(1e7 + 3, 1e7 + 2));
  EXPECT_EQ(p->centroid(), Eigen::Vector2d(1e7 + 2, 1e7 + 2.0 / 3.0));
}

// --- SAT against the exact oracle -------------------------------------------------------------

SatResult2 fast(const Shape& a, const Shape& b) {
  if (a.is_box && b.is_box) return collideObb2(a.box, b.box);
  if (a.is_box) return collideObbPolygon(a.box, b.poly);
  if (b.is_box) return collidePolygonObb(a.poly, b.box);
  return collidePolygons(a.poly, b.poly);
}

exact::ExactResult oracle(const Shape& a, const Shape& b) {
  if (a.is_box && b.is_box) return exact::collideObb2(a.box, b.box);
  // A box keeps its exact axes: its rounded corners would tilt its faces far from the origin.
  if (a.is_box) return exact::collideObbPolygon(a.box, b.poly);
  if (b.is_box) return exact::collideObbPolygon(b.box, a.poly);
  return exact::collidePolygons(a.poly, b.poly);
}

using ShapePairMaker = std::function<std::pair<Shape, Shape>(Random&)>;

ClassStats runShapeClass(std::uint64_t seed, const ShapePairMaker& make) {
  return testing::runPairClass(
      seed, make, [](const Shape& a, const Shape& b, int i, Failures& f, ClassStats& stats) {
        const exact::ExactResult ex = oracle(a, b);
        const SatResult2 ab = fast(a, b);
        const SatResult2 ba = fast(b, a);
        const auto pa = a.points(), pb = b.points();
        const Eigen::Vector2d ref = a.anchor();
        testing::checkAgainstExact(ab, ex.hit, ex.separation, pa, pb, ref, i, f, stats);
        testing::checkAgainstExact(ba, ex.hit, ex.separation, pb, pa, ref, i, f, stats);
        const double asym = std::abs(ab.separation - ba.separation);
        stats.noteAsymmetry(asym);
        f.check(asym <= 1e-9, i, "sep not symmetric");
        f.check(std::abs(testing::signedGap(pa, pb, -ba.normal, ref) - ab.separation) <=
                    testing::kSepTolerance,
                i, "reversed normal does not realise sep");
        if (i % 10 == 0) {
          Shape apart = b;
          apart.translate(ab.normal * (1e-5 - ab.separation));
          f.check(!oracle(a, apart).hit, i, "moving B out along the normal did not separate");
        }
        return ex;
      });
}

std::pair<Shape, Shape> nearTouching(Random& rng, const Eigen::Vector2d& base) {
  Shape a = randomShape(rng, base, 0.1, 20.0, true);
  Shape b = randomShape(rng, base, 0.1, 20.0, !a.is_box);
  return placedNearTouching(rng, a, b);
}

TEST(ConvexPolygonRandom, GapsOnBothSidesOfTouching) {
  const ClassStats s =
      runShapeClass(2001, [](Random& rng) { return nearTouching(rng, rng.offset(0, 100)); });
  EXPECT_GT(s.exact_hits, s.cases / 3);
  EXPECT_LT(s.exact_hits, 2 * s.cases / 3);
}

TEST(ConvexPolygonRandom, Quadrilaterals) {
  const ClassStats s = runShapeClass(2006, quadrilateralPair);
  EXPECT_GT(s.exact_hits, s.cases / 4);
  EXPECT_LT(s.exact_hits, 3 * s.cases / 4);
}

TEST(ConvexPolygonRandom, FarFromOrigin) {
  const ClassStats s = runShapeClass(2002, [](Random& rng) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    if (rng.integer(0, 1) == 0) return nearTouching(rng, base);
    Shape a = randomShape(rng, base, 0.1, 20.0, true);
    Shape b = randomShape(rng, base + rng.offset(0, 20), 0.1, 20.0, !a.is_box);
    return std::pair{a, b};
  });
  EXPECT_GT(s.exact_hits, s.cases / 10);
}

TEST(ConvexPolygonRandom, Containment) {
  const ClassStats s = runShapeClass(2003, [](Random& rng) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    Shape a = randomShape(rng, base, 1.0, 100.0, true);
    const ConvexPolygon pa = a.asPolygon();
    const Eigen::Vector2d c = pa.centroid();
    // Distance from the centroid to the nearest edge line: a disc of that radius is inside A.
    double inner = INFINITY;
    for (int i = 0; i < pa.count; ++i) {
      const Eigen::Vector2d e = (pa.vertex((i + 1) % pa.count) - pa.vertex(i)).normalized();
      inner = std::min(inner,
                       std::abs((c - pa.vertex(i)).x() * e.y() - (c - pa.vertex(i)).y() * e.x()));
    }
    const double r = 0.45 * inner;
    Shape b = randomShape(rng, c + rng.offset(0, r), 0.01 * r, r, !a.is_box);
    return std::pair{a, b};
  });
  EXPECT_EQ(s.exact_hits, s.cases) << "every contained pair overlaps";
}

// B is A turned half a turn about one of A's vertices: the two touch at exactly that vertex. On a
// 1/64 m grid every product in the test is exact, so the fast SAT must find sep == 0 too.
TEST(ConvexPolygonRandom, ExactTouchingAtAVertex) {
  const ClassStats s = runShapeClass(2004, [](Random& rng) {
    const Eigen::Vector2d base{std::round(rng.uniform(-1e7, 1e7)),
                               std::round(rng.uniform(-1e7, 1e7))};
    for (;;) {
      const ConvexPolygon raw = rng.polygon(Eigen::Vector2d::Zero(), 0.5, 40.0);
      std::vector<Eigen::Vector2d> grid, turned;
      for (int i = 0; i < raw.count; ++i)
        grid.push_back(base + (raw.vertex(i) * 64).array().round().matrix() / 64);
      const Eigen::Vector2d pivot = grid[static_cast<std::size_t>(rng.integer(0, raw.count - 1))];
      for (const Eigen::Vector2d& p : grid) turned.push_back(2 * pivot - p);
      auto a = ConvexPolygon::fromPoints(grid), b = ConvexPolygon::fromPoints(turned);
      if (a && b) return std::pair{Shape{false, {}, *a}, Shape{false, {}, *b}};
    }
  });
  EXPECT_EQ(s.exact_hits, s.cases);
  EXPECT_EQ(s.max_error, 0.0);
}

// --- named cases ------------------------------------------------------------------------------

ConvexPolygon poly(std::vector<Eigen::Vector2d> points) {
  auto p = ConvexPolygon::fromPoints(points);
  EXPECT_TRUE(p.has_value());
  return p.value_or(ConvexPolygon{});
}

TEST(ConvexPolygonSat, SharedEdgeIsAHit) {
  const ConvexPolygon a = poly({{0, 0}, {2, 0}, {1, 2}});
  const ConvexPolygon b = poly({{0, 0}, {2, 0}, {1, -3}});
  for (const SatResult2& r : {collidePolygons(a, b), collidePolygons(b, a)}) {
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.separation, 0.0);
  }
}

TEST(ConvexPolygonSat, PolygonAgainstBoxAtRightAngles) {
  const ConvexPolygon kerb = poly({{1e7, 0}, {1e7 + 4, 0}, {1e7 + 4, 1}, {1e7, 1}});
  for (int heading : {0, 90, 180, 270}) {
    SCOPED_TRACE(heading);
    const Obb2 car = Obb2::fromDegrees({1e7 + 2, 1 + 0.875}, heading, 1.75, 1.75);
    const SatResult2 pb = collidePolygonObb(kerb, car);
    const SatResult2 bp = collideObbPolygon(car, kerb);
    EXPECT_TRUE(pb.hit);
    EXPECT_TRUE(bp.hit);
    EXPECT_EQ(pb.separation, 0.0);
    EXPECT_EQ(bp.separation, 0.0);
    EXPECT_EQ(pb.normal, Eigen::Vector2d(0, 1));
    EXPECT_EQ(bp.normal, Eigen::Vector2d(0, -1));
  }
}

TEST(ConvexPolygonSat, SeparatedTriangles) {
  const ConvexPolygon a = poly({{0, 0}, {1, 0}, {0, 1}});
  const ConvexPolygon b = poly({{1, 1}, {2, 1}, {1, 2}});
  const SatResult2 r = collidePolygons(a, b);
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(r.normal.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(r.normal.y(), std::sqrt(0.5), 1e-15);
}

TEST(ConvexPolygonSat, BoxPolygonMatchesBoxBox) {
  Random rng(2005);
  for (int i = 0; i < 1000; ++i) {
    const Obb2 a = rng.box(rng.farPoint(1e7), 0.1, 10.0);
    const Obb2 b = rng.box(a.center + rng.offset(0, 10), 0.1, 10.0);
    const SatResult2 boxes = collideObb2(a, b);
    const SatResult2 mixed = collideObbPolygon(a, ConvexPolygon::fromObb(b));
    EXPECT_NEAR(boxes.separation, mixed.separation, 1e-8);
  }
}

}  // namespace
}  // namespace cardemo
