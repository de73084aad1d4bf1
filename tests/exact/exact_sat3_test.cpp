/// Exact 3D SAT oracle on hand-made boxes with known answers.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "compare/exact/exact_sat.hpp"

namespace cardemo {
namespace {

Obb3 cube(const Eigen::Vector3d& center) {
  return Obb3::fromQuaternion(center, Eigen::Quaterniond::Identity(), {2, 2, 2});
}

TEST(ExactSat3, AxisAlignedGapOfOneMetre) {
  const exact::ExactResult r = exact::collideObb3(cube({0, 0, 0}), cube({0, 3, 0}));
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(r.separation, 1.0);
}

TEST(ExactSat3, AxisAlignedPenetrationOfAQuarter) {
  const exact::ExactResult r = exact::collideObb3(cube({0, 0, 0}), cube({-1.75, 0.5, 0.25}));
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.separation, -0.25);
}

TEST(ExactSat3, FaceTouchingIsAHitAtZero) {
  const exact::ExactResult r = exact::collideObb3(cube({1e7, 0, 0}), cube({1e7, 0.5, -2}));
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.separation, 0.0);
}

TEST(ExactSat3, CoincidentBoxesPenetrateByTheSmallestWidth) {
  const Obb3 a =
      Obb3::fromQuaternion({3, 4, 5}, Eigen::Quaterniond(0.3, -0.1, 0.7, 0.2), {8, 1, 3});
  const exact::ExactResult r = exact::collideObb3(a, a);
  EXPECT_TRUE(r.hit);
  EXPECT_NEAR(r.separation, -1.0, 1e-15);
}

// A turned 45 degrees about x (its top is an edge along x at height sqrt 2), B turned 45 degrees
// about y (its bottom is an edge along y). The skew edges are closest along x cross y = z: gap
// cz - 2 sqrt 2, larger than every face axis gap (those are about -0.59 for cz = 3).
TEST(ExactSat3, EdgeEdgeAxisGivesTheGap) {
  const double h = std::sqrt(0.5);
  for (const double cz : {3.0, 2.5}) {
    const Obb3 a = Obb3::fromQuaternion(
        {0, 0, 0},
        Eigen::Quaterniond(std::cos(std::numbers::pi / 8), std::sin(std::numbers::pi / 8), 0, 0),
        {2, 2, 2});
    const Obb3 b = Obb3::fromQuaternion(
        {0, 0, cz},
        Eigen::Quaterniond(std::cos(std::numbers::pi / 8), 0, std::sin(std::numbers::pi / 8), 0),
        {2, 2, 2});
    ASSERT_NEAR(a.rotation()(2, 1), h, 1e-15);  // the intended 45 degree turns
    ASSERT_NEAR(b.rotation()(0, 2), h, 1e-15);
    const exact::ExactResult r = exact::collideObb3(a, b);
    EXPECT_NEAR(r.separation, cz - 4.0 * h, 1e-14) << cz;
    EXPECT_EQ(r.hit, cz < 4.0 * h) << cz;
    const exact::ExactResult s = exact::collideObb3(b, a);
    EXPECT_EQ(s.separation, r.separation);
    EXPECT_EQ(s.hit, r.hit);
  }
}

// The oracle treats the stored matrix as a parallelepiped: a sheared B whose third edge is (1,0,1)
// reaches down to z = cz - 1, and its slanted faces do not give a larger gap.
TEST(ExactSat3, ShearedParallelepiped) {
  Obb3 b;
  b.center = {0, 0, 5};
  Eigen::Matrix3d sheared;
  sheared << 1, 0, 1, 0, 1, 0, 0, 0, 1;
  b.setRotation(sheared);
  const exact::ExactResult r = exact::collideObb3(cube({0, 0, 0}), b);
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(r.separation, 3.0);
}

// Exact: swapping the boxes gives the same axes (up to sign) and hence bit-identical answers.
TEST(ExactSat3, SymmetricInTheArguments) {
  std::mt19937_64 rng(0xe3a7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 500; ++k) {
    const auto box = [&] {
      const Eigen::Vector3d center{g(rng), g(rng), g(rng)};
      const Eigen::Quaterniond q{g(rng), g(rng), g(rng), g(rng)};
      const Eigen::Vector3d size{1 + std::abs(g(rng)), 1 + std::abs(g(rng)), 1 + std::abs(g(rng))};
      return Obb3::fromQuaternion(center, q, size);
    };
    const Obb3 a = box(), b = box();
    const exact::ExactResult ab = exact::collideObb3(a, b), ba = exact::collideObb3(b, a);
    ASSERT_EQ(ab.hit, ba.hit);
    ASSERT_EQ(ab.separation, ba.separation);
    ASSERT_EQ(ab.hit, ab.separation <= 0.0);
  }
}

}  // namespace
}  // namespace cardemo
