#include "sim/gate_course.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "../support/random_draws.hpp"
#include "geometry/obb2.hpp"
#include "scene_builders.hpp"
#include "sim/parking_goal.hpp"
#include "sim/parking_readout.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using V = Eigen::Vector2d;

Gate lineGate(std::string name, V from, V to) {
  Gate g;
  g.kind = Gate::Kind::kLine;
  g.name = std::move(name);
  g.from = from;
  g.to = to;
  g.center = 0.5 * (from + to);
  return g;
}

// A line gate that must be crossed towards `side` (+1: to the left of from -> to).
Gate directedLineGate(std::string name, V from, V to, int side) {
  Gate g = lineGate(std::move(name), from, to);
  const V along = to - from;
  g.direction =
      side > 0 ? V(-along.y(), along.x()).normalized() : V(along.y(), -along.x()).normalized();
  g.side = side;
  return g;
}

Gate boxGate(std::string name, V center, double length, double width) {
  Gate g;
  g.kind = Gate::Kind::kBox;
  g.name = std::move(name);
  g.center = center;
  g.corners = Obb2::fromDegrees(center, 0.0, length, width).corners();
  return g;
}

// Runs the course along a path of centre positions; returns the frames at which gates passed.
GateCourse run(std::vector<Gate> gates, const std::vector<V>& path) {
  GateCourse course(std::move(gates));
  course.start(path.front());
  for (std::size_t k = 1; k < path.size(); ++k) {
    course.step(path[k - 1], path[k], static_cast<std::int64_t>(k));
  }
  return course;
}

// The gate across the x axis at x = 0, from y = -1 to y = 1: its left is -x.
Gate across() {
  return lineGate("across", {0, -1}, {0, 1});
}

TEST(GateCourse, CrossingTheLinePassesIt) {
  const GateCourse c = run({across()}, {{-1, 0}, {-0.5, 0}, {0.5, 0}});
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.passedFrame(0), 2);
}

TEST(GateCourse, PassingBesideTheLineDoesNot) {
  EXPECT_FALSE(run({across()}, {{-1, 2}, {1, 2}}).done());
  EXPECT_FALSE(run({across()}, {{-1, 1.0001}, {1, 1.0001}}).done());
}

TEST(GateCourse, ThroughTheEndPointCounts) {
  // The path passes exactly through the gate's end (0, 1): the gate is a closed segment.
  const GateCourse c = run({across()}, {{-1, 0}, {1, 2}});
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.passedFrame(0), 1);
}

TEST(GateCourse, TouchingTheLineAndTurningBackIsNoCrossing) {
  const GateCourse c = run({across()}, {{-1, 0}, {0, 0.5}, {0, 0.25}, {-1, 0.5}});
  EXPECT_FALSE(c.done());
}

TEST(GateCourse, StoppingOnTheLineThenGoingOnCountsOnTheStepThatLeavesIt) {
  const GateCourse c = run({across()}, {{-1, 0}, {0, 0}, {0, 0}, {0, 0.5}, {1, 0.5}});
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.passedFrame(0), 4);
}

TEST(GateCourse, LeavingTheLineBeyondItsEndIsNoCrossing) {
  // Onto the line inside the gate, along the line past its end, then off to the other side.
  EXPECT_FALSE(run({across()}, {{-1, 0}, {0, 0.5}, {0, 3}, {1, 3}}).done());
}

TEST(GateCourse, CrossingBackLeavesItPassedOnce) {
  const GateCourse c =
      run({across(), lineGate("far", {5, -1}, {5, 1})}, {{-1, 0}, {1, 0}, {-1, 0}, {1, 0}});
  EXPECT_EQ(c.passed(), 1u);
  EXPECT_EQ(c.passedFrame(0), 1);
  EXPECT_EQ(c.misses(), 0);
}

TEST(GateCourse, WrongDirectionDoesNotPassAndSaysSo) {
  // Must be crossed towards -x (the left of (0,-1) -> (0,1)).
  const Gate g = directedLineGate("west", {0, -1}, {0, 1}, +1);
  GateCourse c = run({g}, {{-1, 0}, {1, 0}});
  EXPECT_FALSE(c.done());
  ASSERT_TRUE(c.lastNotice().has_value());
  EXPECT_EQ(c.lastNotice()->kind, GateNotice::Kind::kWrongWay);
  EXPECT_EQ(gateNoticeText(c, *c.lastNotice()), "gate 1 the wrong way: west");
  // Back through it: now the right way.
  c.step({1, 0}, {-1, 0}, 2);
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.lastNotice()->kind, GateNotice::Kind::kPassed);
  EXPECT_EQ(run({g}, {{1, 0}, {-1, 0}}).passed(), 1u);
}

TEST(GateCourse, ALaterGateFirstIsAMissNamingTheSkippedGate) {
  const std::vector<Gate> gates{lineGate("one", {0, 1}, {0, 3}), lineGate("two", {2, -1}, {2, 1}),
                                lineGate("three", {4, -1}, {4, 1})};
  // Along y = 0: gate one (at y 1..3) is passed beside, gate two is crossed first.
  GateCourse c = run(gates, {{-1, 0}, {3, 0}});
  EXPECT_EQ(c.passed(), 0u);
  EXPECT_EQ(c.misses(), 1);
  ASSERT_TRUE(c.lastMiss().has_value());
  EXPECT_EQ(c.lastMiss()->gate, 0u);
  EXPECT_EQ(c.lastMiss()->frame, 1);
  EXPECT_EQ(gateNoticeText(c, *c.lastMiss()), "missed gate 1: one");
  EXPECT_EQ(nextGateText(c), "next gate 1: one");
  // Back, through gate one, then on through two and three: all in order now.
  c.step({3, 0}, {-1, 0}, 2);
  c.step({-1, 0}, {-1, 2}, 3);
  c.step({-1, 2}, {1, 2}, 4);
  c.step({1, 2}, {1, 0}, 5);
  c.step({1, 0}, {5, 0}, 6);
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.passedFrame(0), 4);
  EXPECT_EQ(c.passedFrame(1), 6);
  EXPECT_EQ(c.passedFrame(2), 6);  // two gates on one step, taken in order
  EXPECT_EQ(nextGateText(c), "");
}

TEST(GateCourse, BoxIsPassedWhenThePathMeetsIt) {
  const Gate box = boxGate("box", {0, 0}, 2, 2);
  EXPECT_TRUE(run({box}, {{-3, 0}, {-1, 0}}).done());  // ends on its edge
  EXPECT_TRUE(run({box}, {{-3, -3}, {3, 3}}).done());  // through it in one step
  EXPECT_TRUE(run({box}, {{-3, 1}, {3, 1}}).done());   // along its edge
  EXPECT_FALSE(run({box}, {{-3, 1.001}, {3, 1.001}}).done());
  Gate east = box;
  east.direction = V(1, 0);
  EXPECT_TRUE(run({east}, {{-3, 0}, {-0.5, 0}}).done());
  EXPECT_FALSE(run({east}, {{3, 0}, {0.5, 0}}).done());
  EXPECT_FALSE(run({east}, {{0, 0}, {0, 0}}).done());  // standing inside is no advance
}

// --- the brute-force twin: the rule read off the whole path, in rationals, every step ---

int exactSide(const Gate& g, const V& p) {
  const mpq_class d = (mpq_class(g.to.x()) - g.from.x()) * (mpq_class(p.y()) - g.from.y()) -
                      (mpq_class(g.to.y()) - g.from.y()) * (mpq_class(p.x()) - g.from.x());
  return sgn(d);
}

bool exactMeet(const V& p0, const V& p1, const V& a, const V& b) {
  // Sampling-free: intersect the two lines' parameters in rationals.
  const mpq_class rx = mpq_class(p1.x()) - p0.x(), ry = mpq_class(p1.y()) - p0.y();
  const mpq_class sx = mpq_class(b.x()) - a.x(), sy = mpq_class(b.y()) - a.y();
  const mpq_class qx = mpq_class(a.x()) - p0.x(), qy = mpq_class(a.y()) - p0.y();
  const mpq_class den = rx * sy - ry * sx;
  if (den != 0) {
    const mpq_class t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
    return t >= 0 && t <= 1 && u >= 0 && u <= 1;
  }
  // Parallel (the gates have a != b): only a shared line can meet; then compare along it.
  if (qx * ry - qy * rx != 0 || (rx == 0 && ry == 0 && qx * sy - qy * sx != 0)) return false;
  const mpq_class t0 = 0, t1 = sx * sx + sy * sy;                          // a and b along s
  const mpq_class u0 = -(qx * sx + qy * sy), u1 = u0 + rx * sx + ry * sy;  // p0, p1 along s
  return std::max(std::min(u0, u1), t0) <= std::min(std::max(u0, u1), t1);
}

// Gate i is crossed the right way on step k (path[k-1] -> path[k]) by the rule in the header,
// found from the whole path rather than from kept state.
bool crossedAt(const Gate& g, const std::vector<V>& path, std::size_t k) {
  const int side = exactSide(g, path[k]);
  if (side == 0) return false;
  int before = 0;
  for (std::size_t j = k; j-- > 0;) {
    if (const int s = exactSide(g, path[j]); s != 0) {
      before = s;
      break;
    }
  }
  if (before == 0 || before == side) return false;
  if (!exactMeet(path[k - 1], path[k], g.from, g.to)) return false;
  return g.side == 0 || g.side == side;
}

double gridCoordinate(std::mt19937_64& rng) {
  // Half-metre steps make touching, stopping on a line and collinear runs common.
  if (testing::uniformInt(rng, 0, 3) == 0) return testing::uniform(rng, -3.0, 3.0);
  return 0.5 * testing::uniformInt(rng, -6, 6);
}

TEST(GateCourse, MatchesTheRuleReadOffTheWholePathOnRandomPaths) {
  std::mt19937_64 rng(4242);
  std::int64_t passes = 0;
  std::int64_t misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<Gate> gates;
    const int count = testing::uniformInt(rng, 1, 4);
    for (int i = 0; i < count; ++i) {
      V a{gridCoordinate(rng), gridCoordinate(rng)};
      V b{gridCoordinate(rng), gridCoordinate(rng)};
      if (a == b) b.x() += 1.0;
      const int side = testing::uniformInt(rng, -1, 1);
      gates.push_back(side == 0 ? lineGate("g" + std::to_string(i), a, b)
                                : directedLineGate("g" + std::to_string(i), a, b, side));
    }
    std::vector<V> path{{gridCoordinate(rng), gridCoordinate(rng)}};
    const int steps = testing::uniformInt(rng, 1, 40);
    for (int k = 0; k < steps; ++k) {
      const int move = testing::uniformInt(rng, 0, 5);
      // Stand still, or move a little or far.
      const V next = move == 0  ? path.back()
                     : move < 4 ? V(path.back() + V(0.5 * testing::uniformInt(rng, -2, 2),
                                                    0.5 * testing::uniformInt(rng, -2, 2)))
                                : V(gridCoordinate(rng), gridCoordinate(rng));
      path.push_back(next);
    }
    // The twin: the next gate, advanced by each step's crossings in order; a crossing of a
    // later gate while one is due is a miss.
    std::size_t next = 0;
    std::int64_t twin_misses = 0;
    std::vector<std::int64_t> frames;
    for (std::size_t k = 1; k < path.size(); ++k) {
      while (next < gates.size() && crossedAt(gates[next], path, k)) {
        frames.push_back(static_cast<std::int64_t>(k));
        ++next;
      }
      for (std::size_t j = next + 1; j < gates.size(); ++j) {
        if (crossedAt(gates[j], path, k)) {
          ++twin_misses;
          break;
        }
      }
    }
    const GateCourse c = run(gates, path);
    ASSERT_EQ(c.passed(), next) << "trial " << trial;
    for (std::size_t i = 0; i < next; ++i) ASSERT_EQ(c.passedFrame(i), frames[i]);
    ASSERT_EQ(c.misses(), twin_misses) << "trial " << trial;
    passes += static_cast<std::int64_t>(next);
    misses += twin_misses;
  }
  // Both outcomes occur often enough for the comparison to mean something.
  EXPECT_GT(passes, 1000);
  EXPECT_GT(misses, 100);
}

// --- the gates in a parking challenge ---

TEST(GateCourse, TheBayCountsOnlyAfterEveryGate) {
  // A car at rest in its bay, with a gate behind it: never parked until it drives through it.
  Scene s = test::sceneWith({}, 0.0, 0.0, 0.0);
  Goal goal;
  goal.bay.center = {0.0, 0.0};
  goal.hold_time = 0.0;
  goal.gates.push_back(lineGate("behind", {-3, -2}, {-3, 2}));
  s.goal = goal;
  World world(s);
  ParkingChallenge challenge(goal, world.settings().hz, s.player.health);
  challenge.observe(world);
  for (int i = 0; i < 240; ++i) {
    world.step({});
    challenge.observe(world);
  }
  EXPECT_FALSE(challenge.over());
  EXPECT_EQ(notParkedReasons(challenge), std::vector<std::string>{"next gate 1: behind"});
  EXPECT_EQ(bayReadout(challenge), std::vector<std::string>{"next gate 1: behind"});
  // Without the gate the same car parks at once.
  Goal open = goal;
  open.gates.clear();
  ParkingChallenge free(open, world.settings().hz, s.player.health);
  free.observe(world);
  EXPECT_TRUE(free.parkedFrame().has_value());
}

}  // namespace
}  // namespace cardemo
