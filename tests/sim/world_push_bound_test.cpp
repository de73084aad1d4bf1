// The translation bound of the push-out (SimulationSchemes::translation_bound): after a push, a
// candidate whose separation exceeded the distance pushed is not tested again. Checked against the
// twin that tests every candidate (the contacts, hits and state must be the same every frame) and
// on named cases at the edge of the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../support/test_scale.hpp"
#include "collision/narrow_phase.hpp"
#include "geometry/bit_cast.hpp"
#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::sceneWith;

WorldSettings everyTest() {
  WorldSettings s;
  s.schemes.translation_bound = false;
  return s;
}

std::string bitsOf(double x) {
  return std::to_string(bitCast<std::uint64_t>(x));
}

// The frame's contacts, bit for bit.
std::string describeContacts(const World& w) {
  std::string out;
  for (const ActiveContact& c : w.contacts()) {
    out += std::to_string(c.collider) + " " + bitsOf(c.normal.x()) + " " + bitsOf(c.normal.y()) +
           " " + bitsOf(c.separation) + "; ";
  }
  return out;
}

// A random lot; odd seeds add polygon obstacles in and beside the aisle (a triangle, a turned
// pentagon, a kerb), whose separations come from the polygon SAT.
Scene lotFor(int seed) {
  Scene scene = test::parkingLot(static_cast<std::uint64_t>(seed));
  if (seed % 2 == 1) {
    const std::vector<Eigen::Vector2d> triangle{{6.0, 1.5}, {9.0, 2.5}, {7.0, 3.5}};
    std::vector<Eigen::Vector2d> pentagon;
    for (int k = 0; k < 5; ++k) {
      const double angle = 0.3 + 1.2566370614359172 * k;
      pentagon.push_back({-9.0 + 1.2 * std::cos(angle), -2.0 + 1.2 * std::sin(angle)});
    }
    scene.obstacles.push_back({"triangle", *ConvexPolygon::fromPoints(triangle)});
    scene.obstacles.push_back({"pentagon", *ConvexPolygon::fromPoints(pentagon)});
    scene.obstacles.push_back(test::wallObstacle("kerb", 15.0, -3.0, 15.3, 3.0));
  }
  return scene;
}

TEST(WorldPushBound, SameContactsHitsAndStateAsTestingEveryCandidate) {
  // Random drives through random lots (walls, and on odd seeds polygons, included), near the
  // origin and 1e7 m from it.
  const int drives = testing::scaledCount(40);
  std::int64_t skipped = 0, pushes_tested = 0, polygon_hits = 0;
  for (int seed = 1; seed <= drives; ++seed) {
    for (const double offset : {0.0, 1e7}) {
      const Scene scene = test::translated(lotFor(seed), {offset, -offset});
      World bound(scene), every(scene, everyTest());
      for (const InputFrame& in : test::scriptedDrive(static_cast<std::uint64_t>(seed), 3000)) {
        bound.step(in);
        every.step(in);
        ASSERT_EQ(bound.stateHash(), every.stateHash())
            << "seed " << seed << " offset " << offset << " frame " << bound.frame();
        ASSERT_EQ(describeContacts(bound), describeContacts(every))
            << "seed " << seed << " offset " << offset << " frame " << bound.frame();
      }
      ASSERT_EQ(bound.hits().size(), every.hits().size()) << "seed " << seed;
      EXPECT_EQ(bound.health(), every.health()) << "seed " << seed;
      const WorldStats& b = bound.stats();
      const WorldStats& e = every.stats();
      // The same candidates, each either tested or skipped; the twin skips none.
      EXPECT_EQ(b.broadphase_candidates, e.broadphase_candidates) << "seed " << seed;
      EXPECT_EQ(b.narrowphase_tests + b.skipped_tests, b.broadphase_candidates) << "seed " << seed;
      EXPECT_EQ(e.skipped_tests, 0);
      EXPECT_EQ(e.narrowphase_tests, e.broadphase_candidates);
      for (const HitEvent& h : bound.hits())
        polygon_hits += h.collider >= scene.parked.size() ? 1 : 0;
      skipped += b.skipped_tests;
      pushes_tested += e.narrowphase_tests - b.narrowphase_tests;
    }
  }
  // The drives push out often enough that the bound saves tests.
  EXPECT_GT(skipped, 10 * drives);
  EXPECT_EQ(skipped, pushes_tested);
  EXPECT_GT(polygon_hits, 0);
}

// The player at the origin (facing +x, 4.5 x 1.8 m) overlaps `north` by 0.2 m and is pushed
// 0.1999 m south, towards `south`, turned 45 degrees with its centre at (1.8, y).
struct Sandwich {
  static constexpr double kPush = 0.2 - 1e-4;  // the overlap less the resting depth
  World world;
  std::int64_t tests_before = 0;
  Sandwich(double y, const WorldSettings& settings)
      : world(sceneWith({parkedCar("north", 0.0, 0.9 + 0.9 - 0.2, 0.0),
                         parkedCar("south", 1.8, y, 45.0)}),
              settings) {
    tests_before = world.stats().narrowphase_tests;
    world.step(testing::kNone);
  }
  [[nodiscard]] bool touches(std::uint32_t id) const {
    for (const ActiveContact& c : world.contacts()) {
      if (c.collider == id) return true;
    }
    return false;
  }
};

TEST(WorldPushBound, SkipsExactlyTheCollidersBeyondThePush) {
  // `south` from far below to touching the pushed car: its AABB meets the player's before the
  // push (so it is a candidate whose gap is known), and its SAT separation then crosses the push.
  int skipped = 0, tested_touched = 0, tested_apart = 0;
  for (int i = 0; i <= 250; ++i) {
    const double y = -3.12 + 0.002 * i;
    Sandwich bound(y, {}), every(y, everyTest());
    ASSERT_EQ(bound.world.stateHash(), every.world.stateHash()) << y;
    ASSERT_EQ(describeContacts(bound.world), describeContacts(every.world)) << y;
    ASSERT_TRUE(bound.touches(0)) << y;
    const Obb2 player = Obb2::fromDegrees({0.0, 0.0}, 0.0, 4.5, 1.8);
    const Obb2 south = Obb2::fromDegrees({1.8, y}, 45.0, 4.5, 1.8);
    if (!player.aabb().overlaps(south.aabb())) continue;
    const double gap = collidePlayer(player, south).separation;
    const bool skip = bound.world.stats().skipped_tests == 1;
    ASSERT_LE(bound.world.stats().skipped_tests, 1) << y;
    // Skipped only beyond the push, and always beyond it plus twice the 1e-6 m margin.
    if (skip) {
      EXPECT_GT(gap, Sandwich::kPush) << y;
    }
    if (gap > Sandwich::kPush + 2e-6) {
      EXPECT_TRUE(skip) << y;
    }
    // A skip saves one test, and only that.
    EXPECT_EQ(every.world.stats().narrowphase_tests - every.tests_before,
              bound.world.stats().narrowphase_tests - bound.tests_before + (skip ? 1 : 0))
        << y;
    skipped += skip ? 1 : 0;
    tested_touched += !skip && bound.touches(1) ? 1 : 0;
    tested_apart += !skip && !bound.touches(1) ? 1 : 0;
  }
  // The scan crosses every case: skipped, tested and touched, tested within the push but apart
  // (the push runs at 45 degrees to that gap, closing it by only 0.71 of the push).
  EXPECT_GT(skipped, 10);
  EXPECT_GT(tested_touched, 10);
  EXPECT_GT(tested_apart, 10);
}

TEST(WorldPushBound, TheMarginIsOneMicrometre) {
  // `south` placed (by secant steps on its centre's y) so that its gap is the push plus `excess`:
  // tested at 0.5e-6 m and below, skipped from 3e-6 m on.
  const Obb2 player = Obb2::fromDegrees({0.0, 0.0}, 0.0, 4.5, 1.8);
  const auto gapAt = [&player](double y) {
    return collidePlayer(player, Obb2::fromDegrees({1.8, y}, 45.0, 4.5, 1.8)).separation;
  };
  for (const double excess : {-1e-7, 0.0, 5e-7, 3e-6, 1e-5}) {
    const double target = Sandwich::kPush + excess;
    double y0 = -3.0, y1 = -2.9;
    for (int k = 0; k < 8 && gapAt(y1) != target && gapAt(y1) != gapAt(y0); ++k) {
      const double y2 = y1 - (gapAt(y1) - target) * (y1 - y0) / (gapAt(y1) - gapAt(y0));
      y0 = y1;
      y1 = y2;
    }
    ASSERT_NEAR(gapAt(y1), target, 1e-9) << excess;
    Sandwich bound(y1, {}), every(y1, everyTest());
    EXPECT_EQ(bound.world.stats().skipped_tests, excess >= 3e-6 ? 1 : 0) << excess;
    EXPECT_FALSE(bound.touches(1)) << excess;
    EXPECT_EQ(bound.world.stateHash(), every.world.stateHash()) << excess;
  }
}

}  // namespace
}  // namespace cardemo
