// The bay chain of free drive: which bays are free (against a brute-force search of each row's
// slots), the order they are chained in, and the count of a drive that parks in two of them.

#include "sim/bay_chain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/sat_obb2.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::sceneWith;

// The free-drive lot (assets/scenes/parking-lot.json): rows A (y = 8, facing north) and B (y = -8,
// facing south) with cars every 5 m from x = -35 to 35, row C (y = 26, nose to tail) every 7.5 m
// from -30 to 30, and one car E1 across the east end.
Scene freeDriveLot() {
  Scene s = sceneWith({}, -45.0, 0.0, 0.0);
  s.bounds = Aabb2{{-60.0, -40.0}, {60.0, 40.0}};
  for (int i = 0; i < 15; ++i) {
    const double x = -35.0 + 5.0 * i;
    s.parked.push_back(parkedCar("A" + std::to_string(i + 1), x, 8.0, 90.0));
    s.parked.push_back(parkedCar("B" + std::to_string(i + 1), x, -8.0, 270.0));
  }
  for (int i = 0; i < 9; ++i) {
    s.parked.push_back(parkedCar("C" + std::to_string(i + 1), -30.0 + 7.5 * i, 26.0, 0.0));
  }
  s.parked.push_back(parkedCar("E1", 50.0, 0.0, 90.0));
  return s;
}

TEST(BayChain, TheFreeDriveLotHasABayAtEachEndOfEachRowInARing) {
  const std::vector<FreeBay> bays = findFreeBays(freeDriveLot());
  ASSERT_EQ(bays.size(), 6u);
  // Nearest the start (-45, 0) first (A's west end and B's are equally near: the ring decides),
  // then counter-clockwise around the lot's centre.
  const std::vector<Eigen::Vector2d> expected = {{-40.0, 8.0}, {-40.0, -8.0}, {40.0, -8.0},
                                                 {40.0, 8.0},  {37.5, 26.0},  {-37.5, 26.0}};
  for (std::size_t i = 0; i < bays.size(); ++i) {
    EXPECT_NEAR((bays[i].bay.center - expected[i]).norm(), 0.0, 1e-9) << i;
    EXPECT_EQ(bays[i].id, "bay-" + std::to_string(i + 1));
    EXPECT_DOUBLE_EQ(bays[i].bay.length, 5.5);
    EXPECT_DOUBLE_EQ(bays[i].bay.width, 2.6);
  }
  EXPECT_DOUBLE_EQ(bays[0].bay.heading_deg, 90.0);
  EXPECT_DOUBLE_EQ(bays[1].bay.heading_deg, 270.0);
  EXPECT_DOUBLE_EQ(bays[4].bay.heading_deg, 0.0);
}

TEST(BayChain, NamedEdgeCases) {
  // A gap inside a row is a bay; a lone car is no row.
  Scene gap = sceneWith({parkedCar("a", 0, 0, 90), parkedCar("b", 5, 0, 90),
                         parkedCar("d", 15, 0, 90), parkedCar("lone", 0, 30, 45)});
  std::vector<FreeBay> bays = findFreeBays(gap);
  ASSERT_EQ(bays.size(), 3u);  // x = -5, 10, 20
  // A slot past the bounds, or onto an obstacle, is no bay.
  gap.bounds = Aabb2{{-6.0, -20.0}, {40.0, 40.0}};
  gap.obstacles.push_back({"post", ConvexPolygon::fromObb(Obb2::fromDegrees({20, 0}, 0, 1, 1))});
  bays = findFreeBays(gap);
  ASSERT_EQ(bays.size(), 1u);
  EXPECT_NEAR((bays[0].bay.center - Eigen::Vector2d(10, 0)).norm(), 0.0, 1e-9);
  // Cars too close for a bay beside them give none (each slot's bay would touch a neighbour).
  EXPECT_TRUE(findFreeBays(sceneWith({parkedCar("a", 0, 0, 90), parkedCar("b", 2, 0, 90),
                                      parkedCar("c", 6, 0, 90)}))
                  .empty());
  EXPECT_TRUE(findFreeBays(sceneWith({})).empty());
  EXPECT_TRUE(BayChain(sceneWith({}), 120.0).over());
  // Headings either side of 0 / 360 and within the tolerance are one kind: one row, two ends.
  const std::vector<FreeBay> wrapped = findFreeBays(
      sceneWith({parkedCar("a", 0, 0, 359.9999998), parkedCar("b", 0, 5, 0.0000003)}, 30.0, 0.0));
  ASSERT_EQ(wrapped.size(), 2u);
  // Within the tolerance (0.9e-6 degrees) b is of the row's kind: pitch 5, bays at -5 and 15.
  // Beyond it (2e-6) b stands alone: the row is a and c at pitch 10, bays at -10 and 20.
  const auto bayXs = [](double b_heading) {
    std::vector<double> xs;
    for (const FreeBay& bay : findFreeBays(sceneWith(
             {parkedCar("a", 0, 0, 90), parkedCar("b", 5, 0, b_heading), parkedCar("c", 10, 0, 90)},
             0.0, 30.0))) {
      xs.push_back(bay.bay.center.x());
    }
    std::sort(xs.begin(), xs.end());
    return xs;
  };
  const std::vector<double> same = bayXs(90.0000009);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_NEAR(same[0], -5.0, 1e-9);
  EXPECT_NEAR(same[1], 15.0, 1e-9);
  const std::vector<double> other = bayXs(90.000002);
  ASSERT_EQ(other.size(), 2u);
  EXPECT_NEAR(other[0], -10.0, 1e-9);
  EXPECT_NEAR(other[1], 20.0, 1e-9);
}

// Brute-force twin: every slot of a row's lattice from one pitch before its first car to one past
// its last, kept when no car stands on it and its box is inside the bounds and touches nothing.
std::vector<Eigen::Vector2d> bruteForceBays(const Scene& s, const Eigen::Vector2d& origin,
                                            const Eigen::Vector2d& along, double pitch, int lo,
                                            int hi, double heading, double length, double width) {
  std::vector<Eigen::Vector2d> out;
  for (int k = lo - 1; k <= hi + 1; ++k) {
    const Eigen::Vector2d c = origin + along * (pitch * k);
    bool taken = false;
    for (const ParkedCar& car : s.parked) taken = taken || (car.box.center - c).norm() < 1e-6;
    if (taken) continue;
    const Obb2 box = Obb2::fromDegrees(c, heading, length + 1.0, width + 0.8);
    bool free = true;
    for (const ParkedCar& car : s.parked) free = free && !overlapObb2(box, car.box);
    const Aabb2 a = box.aabb();
    free = free && (a.min.array() >= s.bounds->min.array()).all() &&
           (a.max.array() <= s.bounds->max.array()).all();
    if (free) out.push_back(c);
  }
  return out;
}

TEST(BayChain, RandomRowsMatchTheBruteForceSearch) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double heading = std::floor(unit(rng) * 360.0);
    const bool side_by_side = unit(rng) < 0.5;
    const double length = 3.5 + 2.0 * unit(rng);
    const double width = 1.5 + 0.6 * unit(rng);
    const double row_deg = side_by_side ? heading + 90.0 : heading;
    const double pitch = (side_by_side ? width : length) + 0.5 + 4.0 * unit(rng);
    const double r = row_deg * std::acos(-1.0) / 180.0;
    const Eigen::Vector2d along(std::cos(r), std::sin(r));
    const Eigen::Vector2d origin(100.0 * unit(rng) - 50.0, 100.0 * unit(rng) - 50.0);
    Scene s = sceneWith({}, 1000.0, 1000.0);
    s.bounds = Aabb2{{-80.0, -80.0}, {80.0, 80.0}};
    // Slot 0 and slot 1 are always taken (they fix the row's line and pitch); others at random.
    int hi = 1;
    for (int k = 0; k < 10; ++k) {
      if (k > 1 && unit(rng) < 0.3) continue;
      const Eigen::Vector2d c = origin + along * (pitch * k);
      s.parked.push_back(parkedCar("c" + std::to_string(k), c.x(), c.y(), heading, length, width));
      hi = k;
    }
    std::vector<Eigen::Vector2d> expected =
        bruteForceBays(s, origin, along, pitch, 0, hi, heading, length, width);
    std::vector<FreeBay> found = findFreeBays(s);
    ASSERT_EQ(found.size(), expected.size()) << "trial " << trial;
    total += found.size();
    for (const Eigen::Vector2d& c : expected) {
      bool seen = false;
      for (const FreeBay& b : found) {
        seen = seen || (b.bay.center - c).norm() < 1e-6;
        EXPECT_NEAR(std::remainder(b.bay.heading_deg - heading, 360.0), 0.0, 1e-9);
      }
      EXPECT_TRUE(seen) << "trial " << trial << ": no bay at " << c.transpose();
    }
  }
  EXPECT_GT(total, 600u) << "the rows should leave gaps and ends free";
}

// Drives straight along the car's heading line to stop with its centre at `target_along` (m along
// the start heading from the start): throttle while the braking distance leaves room, then Down
// (a press begun while moving brakes and holds), released once stopped. Records the keys.
void driveStraightTo(World& world, BayChain& chain, double target, std::vector<InputFrame>& keys,
                     const Eigen::Vector2d& start, const Eigen::Vector2d& dir) {
  for (int i = 0; i < 2400; ++i) {
    const double at = (world.car().position - start).dot(dir);
    const double v = world.car().speed;
    InputFrame in;
    if (v > 0.0 || at < target - 0.05) {
      const double braking = v * v / (2.0 * 9.0);
      in.up = at + braking + v / 120.0 < target;
      in.down = !in.up;
    }
    if (v == 0.0 && at >= target - 0.05) break;
    keys.push_back(in);
    world.step(in);
    chain.observe(world);
  }
}

// Reverses straight back along `dir` to stop with the car's centre at `target` (m along `dir` from
// `start`, less than where it stands): lets go for a step (a fresh Down at a standstill reverses),
// holds Down while the braking distance leaves room, then Up (a press begun while moving
// backwards brakes and holds) until stopped. Records the keys.
void reverseTo(World& world, BayChain& chain, double target, std::vector<InputFrame>& keys,
               const Eigen::Vector2d& start, const Eigen::Vector2d& dir) {
  keys.emplace_back();
  world.step({});
  chain.observe(world);
  bool braking = false;
  for (int i = 0; i < 2400; ++i) {
    const double at = (world.car().position - start).dot(dir);
    const double v = world.car().speed;
    if (braking && v == 0.0) break;
    braking = braking || at - v * v / (2.0 * 9.0) + v / 120.0 <= target;
    InputFrame in;
    in.down = !braking;
    in.up = braking;
    keys.push_back(in);
    world.step(in);
    chain.observe(world);
  }
}

TEST(BayChain, ASingleBayCountsAgainOnlyAfterTheCarHasLeftIt) {
  // Two cars in a row at x = 0 and 5 facing north; the bounds leave room for the east end's bay
  // only (x = 10), where the car starts.
  Scene row = sceneWith({parkedCar("a", 0, 0, 90), parkedCar("b", 5, 0, 90)}, 10.0, 0.0, 90.0);
  row.bounds = Aabb2{{-6.0, -30.0}, {30.0, 30.0}};
  World world(row);
  BayChain chain(row, 120.0);
  ASSERT_EQ(chain.bays().size(), 1u);
  EXPECT_FALSE(chain.next().has_value());
  chain.observe(world);
  std::vector<InputFrame> keys;
  for (int i = 0; i < 600; ++i) {
    world.step({});
    chain.observe(world);
  }
  EXPECT_EQ(chain.count(), 1) << "standing in the only bay counts it once";
  EXPECT_EQ(chain.current(), 0u);
  driveStraightTo(world, chain, 8.0, keys, {10.0, 0.0}, {0.0, 1.0});
  EXPECT_EQ(chain.count(), 1);
  reverseTo(world, chain, 0.0, keys, {10.0, 0.0}, {0.0, 1.0});
  ASSERT_LT((world.car().position - Eigen::Vector2d(10.0, 0.0)).norm(), 0.6)
      << world.car().position.transpose();
  for (int i = 0; i < 61; ++i) {
    world.step({});
    chain.observe(world);
  }
  EXPECT_EQ(chain.count(), 2) << "back in the bay after leaving it";
  EXPECT_EQ(chain.score().count, 2);
  // Parked within the 61 frames stood (the hold begins once the car is slow enough).
  EXPECT_LE(chain.score().frames, chain.clockFrames());
  EXPECT_GT(chain.score().frames, chain.clockFrames() - 61);
}

TEST(BayChain, MoreBaysThenSoonerIsTheBetterScore) {
  const ChainScore three{3, 12000, 100.0};
  EXPECT_TRUE(three.betterThan({2, 600, 5.0}));
  EXPECT_FALSE((ChainScore{2, 600, 5.0}).betterThan(three));
  EXPECT_TRUE((ChainScore{3, 11880, 99.0}).betterThan(three));
  EXPECT_FALSE(three.betterThan(three)) << "a tie is no better";
}

TEST(BayChain, ParkingTwoBaysCountsTwoAndAReplayRepeatsIt) {
  // The car starts in bay 1 (A's west end), facing south; bay 2 (B's west end) lies 16 m ahead,
  // facing the other way round (either way counts in free drive).
  Scene lot = freeDriveLot();
  lot.player.position = {-40.0, 8.0};
  lot.player.heading_deg = 270.0;
  World world(lot);
  BayChain chain(lot, 120.0);
  chain.observe(world);
  ASSERT_EQ(chain.current(), 0u);
  std::vector<InputFrame> keys;
  for (int i = 0; i < 61; ++i) {
    keys.emplace_back();
    world.step({});
    chain.observe(world);
  }
  EXPECT_EQ(chain.count(), 1);
  EXPECT_EQ(chain.current(), 1u);
  EXPECT_EQ(chain.clockFrames(), 0) << "the clock waits for the car to move";
  driveStraightTo(world, chain, 16.0, keys, {-40.0, 8.0}, {0.0, -1.0});
  ASSERT_LT(std::abs(world.car().position.y() + 8.0), 0.6) << world.car().position.transpose();
  for (int i = 0; i < 61; ++i) {
    keys.emplace_back();
    world.step({});
    chain.observe(world);
  }
  EXPECT_EQ(chain.count(), 2);
  EXPECT_EQ(chain.current(), 2u);
  EXPECT_EQ(chain.next(), 3u);
  EXPECT_GT(chain.clockFrames(), 0);
  EXPECT_LE(chain.score().frames, chain.clockFrames());
  EXPECT_GT(chain.score().frames, chain.clockFrames() - 61) << "the second bay parked just now";
  EXPECT_DOUBLE_EQ(chain.secondsLeft(), 180.0 - static_cast<double>(chain.clockFrames()) / 120.0);
  EXPECT_FALSE(chain.over());

  // The same keys again: the same count (the chain only observes the World).
  World again(lot);
  BayChain replayed(lot, 120.0);
  replayed.observe(again);
  for (const InputFrame& in : keys) {
    again.step(in);
    replayed.observe(again);
  }
  EXPECT_EQ(replayed.count(), 2);
  EXPECT_EQ(replayed.clockFrames(), chain.clockFrames());
}

TEST(BayChain, TheTimeLimitEndsTheChain) {
  Scene lot = freeDriveLot();
  BayChainSettings settings;
  settings.time_limit = 1.0;
  World world(lot);
  BayChain chain(lot, 120.0, settings);
  chain.observe(world);
  InputFrame up;
  up.up = true;
  for (int i = 0; i < 200 && !chain.over(); ++i) {
    world.step(up);
    chain.observe(world);
  }
  EXPECT_TRUE(chain.over());
  EXPECT_TRUE(chain.timedOut());
  EXPECT_FALSE(chain.wrecked());
  EXPECT_EQ(chain.clockFrames(), 120);
  EXPECT_EQ(chain.secondsLeft(), 0.0);
  EXPECT_EQ(chain.count(), 0);
}

}  // namespace
}  // namespace cardemo
