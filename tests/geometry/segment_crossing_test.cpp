#include "geometry/segment_crossing.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "../support/random_draws.hpp"
#include "geometry/exact_sign.hpp"
#include "geometry/obb2.hpp"

namespace cardemo {
namespace {

using V = Eigen::Vector2d;

// --- the slow twins: rationals, exact by construction ---

int rationalOrientation(const V& a, const V& b, const V& c) {
  const mpq_class ax(a.x()), ay(a.y()), bx(b.x()), by(b.y()), cx(c.x()), cy(c.y());
  return sgn((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
}

// p on the closed segment a-b: on its line and inside its bounding box (CLRS 33.1).
bool rationalOnSegment(const V& p, const V& a, const V& b) {
  return rationalOrientation(a, b, p) == 0 && std::min(a.x(), b.x()) <= p.x() &&
         p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

// The textbook test: a proper crossing, or an end point of one on the other.
bool rationalSegmentsMeet(const V& p0, const V& p1, const V& a, const V& b) {
  const int o1 = rationalOrientation(a, b, p0), o2 = rationalOrientation(a, b, p1);
  const int o3 = rationalOrientation(p0, p1, a), o4 = rationalOrientation(p0, p1, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return rationalOnSegment(p0, a, b) || rationalOnSegment(p1, a, b) ||
         rationalOnSegment(a, p0, p1) || rationalOnSegment(b, p0, p1);
}

// A coordinate on a coarse grid (to make touching and collinear cases common) or anywhere.
double coordinate(std::mt19937_64& rng, double offset) {
  if (testing::uniformInt(rng, 0, 2) == 0) return offset + testing::uniform(rng, -4.0, 4.0);
  return offset + 0.5 * testing::uniformInt(rng, -6, 6);
}

V randomPoint(std::mt19937_64& rng, double offset) {
  return {coordinate(rng, offset), coordinate(rng, offset)};
}

TEST(ExactSign, OrientationOfTheObviousCases) {
  EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, -1}), -1);
  EXPECT_EQ(orientation({0, 0}, {1, 0}, {7, 0}), 0);
  EXPECT_EQ(orientation({3, 3}, {3, 3}, {1, 2}), 0);  // a point is no line
}

TEST(ExactSign, OrientationWhereDoublesGetItWrong) {
  // The points lie one unit in the last place off a line far from the origin: the naive double
  // formula rounds the two products to the same value.
  const double far = 1e7;
  const V a{far, far};
  const V b{far + 1.0, far + 1.0};
  const V c{far + 0.5, std::nextafter(far + 0.5, 2 * far)};
  EXPECT_EQ(orientation(a, b, c), rationalOrientation(a, b, c));
  EXPECT_EQ(orientation(a, b, c), 1);
  EXPECT_EQ(orientation(a, b, V{far + 0.5, far + 0.5}), 0);
}

TEST(ExactSign, OrientationMatchesRationalsOnRandomPoints) {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 20000; ++i) {
    const double offset = i % 2 == 0 ? 0.0 : 1e7 * testing::randomSign(rng);
    const V a = randomPoint(rng, offset), b = randomPoint(rng, offset);
    V c = randomPoint(rng, offset);
    if (i % 3 == 0) c = a + (b - a) * testing::uniform(rng, -2.0, 2.0);  // near the line
    ASSERT_EQ(orientation(a, b, c), rationalOrientation(a, b, c))
        << a.transpose() << " " << b.transpose() << " " << c.transpose();
  }
}

TEST(ExactSign, AdvanceSignMatchesRationals) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const double offset = i % 2 == 0 ? 0.0 : -1e7;
    const V p0 = randomPoint(rng, offset), p1 = randomPoint(rng, offset);
    const V d = testing::uniformInt(rng, 0, 1) == 0
                    ? V{1.0, 0.0}
                    : V(testing::uniform(rng, -1.0, 1.0), testing::uniform(rng, -1.0, 1.0));
    const mpq_class dot =
        (mpq_class(p1.x()) - p0.x()) * d.x() + (mpq_class(p1.y()) - p0.y()) * d.y();
    ASSERT_EQ(signOfAdvance(p0, p1, d), sgn(dot));
  }
}

TEST(SegmentCrossing, NamedCases) {
  // Crossing in the middle; touching an end point; touching end to end; missing past the end.
  EXPECT_TRUE(segmentsMeet({0, -1}, {0, 1}, {-1, 0}, {1, 0}));
  EXPECT_TRUE(segmentsMeet({1, -1}, {1, 1}, {-1, 0}, {1, 0}));       // through the end point
  EXPECT_TRUE(segmentsMeet({1, 0}, {2, 5}, {-1, 0}, {1, 0}));        // starts on the end point
  EXPECT_FALSE(segmentsMeet({1.5, -1}, {1.5, 1}, {-1, 0}, {1, 0}));  // past the end
  EXPECT_FALSE(segmentsMeet({0, 0.5}, {0, 1}, {-1, 0}, {1, 0}));     // stops short
  EXPECT_TRUE(segmentsMeet({0, 1}, {0, 0}, {-1, 0}, {1, 0}));        // ends on the gate
  // On one line: overlapping, touching end to end, apart.
  EXPECT_TRUE(segmentsMeet({-3, 0}, {0, 0}, {-1, 0}, {1, 0}));
  EXPECT_TRUE(segmentsMeet({-3, 0}, {-1, 0}, {-1, 0}, {1, 0}));
  EXPECT_FALSE(segmentsMeet({-3, 0}, {-1.5, 0}, {-1, 0}, {1, 0}));
  // A standing car (a point path) on the gate and beside it.
  EXPECT_TRUE(segmentsMeet({0.25, 0}, {0.25, 0}, {-1, 0}, {1, 0}));
  EXPECT_FALSE(segmentsMeet({0.25, 0.1}, {0.25, 0.1}, {-1, 0}, {1, 0}));
  EXPECT_FALSE(segmentsMeet({3, 0}, {3, 0}, {-1, 0}, {1, 0}));
}

TEST(SegmentCrossing, MeetMatchesRationalsOnRandomSegments) {
  std::mt19937_64 rng(2024);
  int met = 0;
  for (int i = 0; i < 40000; ++i) {
    const double offset = i % 4 == 0 ? 1e7 : 0.0;
    const V p0 = randomPoint(rng, offset), a = randomPoint(rng, offset);
    const V p1 = i % 5 == 0 ? p0 : randomPoint(rng, offset);
    const V b = i % 7 == 0 ? a : randomPoint(rng, offset);
    const bool want = rationalSegmentsMeet(p0, p1, a, b);
    met += want ? 1 : 0;
    ASSERT_EQ(segmentsMeet(p0, p1, a, b), want)
        << p0.transpose() << " -> " << p1.transpose() << " vs " << a.transpose() << " -> "
        << b.transpose();
    ASSERT_EQ(segmentsMeet(a, b, p0, p1), want);  // symmetric
    ASSERT_EQ(segmentsMeet(p1, p0, b, a), want);  // either direction
  }
  EXPECT_GT(met, 4000);  // the draw makes both answers common
  EXPECT_LT(met, 36000);
}

TEST(SegmentCrossing, QuadMatchesItsEdgesAndInside) {
  std::mt19937_64 rng(99);
  for (int i = 0; i < 5000; ++i) {
    const Obb2 box =
        Obb2::fromDegrees(randomPoint(rng, 0.0), testing::uniform(rng, 0.0, 360.0),
                          testing::uniform(rng, 0.5, 4.0), testing::uniform(rng, 0.5, 4.0));
    const std::array<V, 4> c = box.corners();
    const V p0 = randomPoint(rng, 0.0), p1 = randomPoint(rng, 0.0);
    bool want = false;
    for (const V& p : {p0, p1}) {
      bool inside = true;
      for (int k = 0; k < 4; ++k)
        inside = inside && rationalOrientation(c[k], c[(k + 1) % 4], p) >= 0;
      want = want || inside;
    }
    for (int k = 0; k < 4; ++k) want = want || rationalSegmentsMeet(p0, p1, c[k], c[(k + 1) % 4]);
    ASSERT_EQ(segmentMeetsQuad(p0, p1, c), want);
  }
}

}  // namespace
}  // namespace cardemo
