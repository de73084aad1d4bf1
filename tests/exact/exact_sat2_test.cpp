#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "geometry/angle.hpp"

namespace cardemo::exact {
namespace {

Obb2 square(double x, double y, double heading_deg = 0.0, double side = 2.0) {
  return Obb2::fromDegrees({x, y}, heading_deg, side, side);
}

ConvexPolygon polygon(std::vector<Eigen::Vector2d> points) {
  auto p = ConvexPolygon::fromPoints(points);
  EXPECT_TRUE(p.has_value());
  return p.value_or(ConvexPolygon{});
}

TEST(ExactObb2, GapOfExactlyOneMetre) {
  const ExactResult r = exact::collideObb2(square(0, 0), square(3, 0));
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(r.separation, 1.0);
}

TEST(ExactObb2, PenetrationOfHalfAMetre) {
  const ExactResult r = exact::collideObb2(square(0, 0), square(0.25, 1.5));
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.separation, -0.5);
}

TEST(ExactObb2, ExactTouchingIsAHitWithZeroSeparation) {
  for (const Obb2& b : {square(2, 0), square(2, 2), square(-2, 1.5, 90), square(0.5, -2, 180)}) {
    const ExactResult r = exact::collideObb2(square(0, 0), b);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.separation, 0.0);
  }
}

TEST(ExactObb2, TinyGapIsDecidedExactly) {
  const double gap = std::ldexp(1.0, -40);
  const ExactResult apart =
      exact::collideObb2(square(0, 0), square(2 + 4 * gap, 0, 0, 2 + 2 * gap));
  EXPECT_FALSE(apart.hit);
  EXPECT_EQ(apart.separation, 3 * gap);
  const ExactResult far = exact::collideObb2(square(1e7, 1e7), square(1e7 + 2, 1e7 + 1));
  EXPECT_TRUE(far.hit);
  EXPECT_EQ(far.separation, 0.0);
}

// B's corner points at A's right face: the gap is 3 - 1 - sqrt(2) (B's half-diagonal).
TEST(ExactObb2, Rotated45CornerTowardsFace) {
  const ExactResult r = exact::collideObb2(square(0, 0), square(3, 0, 45));
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, 2.0 - std::sqrt(2.0), 1e-15);
}

// Along B's diagonal axis the centres are 2*sqrt(2) apart, A reaches sqrt(2) and B reaches 1.
TEST(ExactObb2, Rotated45OnTheDiagonal) {
  const ExactResult r = exact::collideObb2(square(0, 0), square(2, 2, 45));
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, std::sqrt(2.0) - 1.0, 1e-15);
  const ExactResult swapped = exact::collideObb2(square(2, 2, 45), square(0, 0));
  EXPECT_EQ(swapped.separation, r.separation);
  EXPECT_FALSE(swapped.hit);
}

TEST(ExactObb2, ContainmentSeparationIsTheSmallestEscape) {
  // B (side 1) inside A (side 10), 1 m from A's right face: escaping needs 1 + 1 = 2 m.
  const ExactResult r = exact::collideObb2(square(0, 0, 0, 10), square(3.5, 0, 0, 1));
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.separation, -2.0);
}

TEST(ExactPolygons, TriangleAndSquare) {
  const ConvexPolygon tri = polygon({{0, 0}, {1, 0}, {0, 1}});
  const ConvexPolygon touching = polygon({{1, 0}, {2, 0}, {2, 1}, {1, 1}});
  const ExactResult t = exact::collidePolygons(tri, touching);
  EXPECT_TRUE(t.hit);
  EXPECT_EQ(t.separation, 0.0);
  const ConvexPolygon apart = polygon({{2, 0}, {3, 0}, {3, 1}, {2, 1}});
  const ExactResult a = exact::collidePolygons(tri, apart);
  EXPECT_FALSE(a.hit);
  EXPECT_EQ(a.separation, 1.0);
  EXPECT_EQ(exact::collidePolygons(apart, tri).separation, 1.0);
}

// Across the hypotenuse x + y = 1: the square's nearest corner (1, 1) is 1/sqrt(2) away.
TEST(ExactPolygons, GapAcrossASlantedEdge) {
  const ConvexPolygon tri = polygon({{0, 0}, {1, 0}, {0, 1}});
  const ConvexPolygon sq = polygon({{1, 1}, {2, 1}, {2, 2}, {1, 2}});
  const ExactResult r = exact::collidePolygons(tri, sq);
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, std::sqrt(0.5), 1e-16);
}

TEST(ExactPolygons, MatchesBoxOracleForAxisAlignedBoxes) {
  const Obb2 a = square(0, 0), b = square(2.5, 1.25, 90);
  const ExactResult boxes = exact::collideObb2(a, b);
  const ExactResult polys =
      exact::collidePolygons(ConvexPolygon::fromObb(a), ConvexPolygon::fromObb(b));
  EXPECT_EQ(boxes.hit, polys.hit);
  EXPECT_EQ(boxes.separation, polys.separation);
  EXPECT_EQ(boxes.separation, 0.5);
}

TEST(ExactObbPolygon, MatchesTheBoxOracleOnABoxShapedPolygon) {
  const Obb2 a = square(0, 0, 30), b = square(2.5, 1.25, 90);
  const ExactResult boxes = exact::collideObb2(a, b);
  const ExactResult mixed = exact::collideObbPolygon(a, ConvexPolygon::fromObb(b));
  EXPECT_EQ(boxes.hit, mixed.hit);
  EXPECT_NEAR(boxes.separation, mixed.separation, 1e-15);
}

// Found by fuzz_sat2 in CI: a 1 cm box 1e7 m out and a polygon 169 m away. The box's own axes give
// the gap 169.1396442837778 m (also what 80-bit arithmetic gives); the box rounded to double
// corners first has faces tilted by ~1e-7 rad, which moves that gap by 7e-6 m, beyond the 2e-6 m
// contract.
TEST(ExactObbPolygon, KeepsTheBoxAxesExactFarFromTheOrigin) {
  Obb2 box;
  box.center = {6999888.0751878992, 6999888.0751878982};
  box.axis = {-0.53350367659923026, 0.84579774595059298};
  box.half = {0.0055028049049539391, 0.0050200814178837892};
  const ConvexPolygon far = polygon({{6999688.0759066623, 6999738.2033362919},
                                     {6999782.4947715709, 6999738.4136396833},
                                     {6999772.1651075268, 6999738.5370188402},
                                     {6999767.8601483647, 6999738.5694730571}});
  const ExactResult r = exact::collideObbPolygon(box, far);
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, 169.1396442837778, 1e-9);
  const ExactResult rounded = exact::collidePolygons(ConvexPolygon::fromObb(box), far);
  EXPECT_GT(std::abs(rounded.separation - r.separation), 2e-6);
}

}  // namespace
}  // namespace cardemo::exact
