// The parking readout: what is still off, in the car's own terms and a driver's order; why a run
// is not parked; each star earned or missed.

#include "sim/parking_readout.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "geometry/angle.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using Kind = ParkingFixKind;
using Words = std::vector<std::string>;

// Bay at (10, 5) facing +y (heading 90), tolerances 0.5 m, 8 degrees, 0.3 m/s; 5.5 x 2.6 m.
Goal readoutGoal() {
  Goal g;
  g.bay.center = {10.0, 5.0};
  g.bay.heading_deg = 90.0;
  g.bay.length = 5.5;
  g.bay.width = 2.6;
  return g;
}

// The readout for a car whose centre is `ahead` m behind the bay's centre along the bay's heading
// and `left` m to its right (so the bay's centre is that far ahead of and left of a car facing
// the bay's way), turned `turn_deg` from the bay's heading, moving at `speed`.
Words readout(const Goal& g, double ahead, double left, double turn_deg = 0.0, double speed = 0.0) {
  const Eigen::Vector2d along = unitFromDegrees(g.bay.heading_deg);
  const Eigen::Vector2d side{-along.y(), along.x()};
  const Eigen::Vector2d position = g.bay.center - along * ahead - side * left;
  return fixTexts(parkingFixes(g, position, unitFromDegrees(g.bay.heading_deg + turn_deg), speed));
}

TEST(ParkingReadout, EachDirectionInTheCarsOwnTerms) {
  const Goal g = readoutGoal();
  EXPECT_EQ(readout(g, 0.9, 0.0), Words{"0.9 m forward"});
  EXPECT_EQ(readout(g, -0.8, 0.0), Words{"0.8 m back"});
  EXPECT_EQ(readout(g, 0.0, 0.7), Words{"0.7 m left"});
  EXPECT_EQ(readout(g, 0.0, -0.6), Words{"0.6 m right"});
  // Along first, then across: the order a driver fixes them in.
  EXPECT_EQ(readout(g, 0.4, -0.4), (Words{"0.4 m forward", "0.4 m right"}));
  EXPECT_EQ(readout(g, -2.0, 1.5), (Words{"2.0 m back", "1.5 m left"}));
}

TEST(ParkingReadout, TheCarsTermsFollowItsHeadingNotTheBays) {
  Goal g = readoutGoal();
  g.either_direction = true;
  // The car faces the other way (heading 270): the bay's centre, 0.9 m further along +y, is
  // behind it, and a bay to the world's left of the bay heading is to the car's right.
  const Eigen::Vector2d position = g.bay.center + Eigen::Vector2d(0.7, -0.9);
  EXPECT_EQ(fixTexts(parkingFixes(g, position, unitFromDegrees(270.0), 0.0)),
            (Words{"0.9 m back", "0.7 m right"}));
  // Facing +x, across the bay: the bay is to the car's left, and the heading is 90 degrees off.
  g.either_direction = false;
  EXPECT_EQ(fixTexts(parkingFixes(g, g.bay.center + Eigen::Vector2d(0.0, -1.2),
                                  unitFromDegrees(0.0), 0.0)),
            (Words{"1.2 m left", "turn 90\xC2\xB0 left"}));
}

TEST(ParkingReadout, HeadingBothWays) {
  const Goal g = readoutGoal();
  EXPECT_EQ(readout(g, 0.0, 0.0, 12.0), Words{"turn 12\xC2\xB0 right"});
  EXPECT_EQ(readout(g, 0.0, 0.0, -9.4), Words{"turn 9\xC2\xB0 left"});
  // Position before heading.
  // Turned 20 degrees right, the car sees the bay's centre ahead and a little to its left.
  EXPECT_EQ(readout(g, 1.0, 0.0, -20.0),
            (Words{"0.9 m forward", "0.3 m left", "turn 20\xC2\xB0 left"}));
  // Just outside the tolerance rounds to at least 1 degree, and shows the whole number.
  Goal tight = g;
  tight.heading_tolerance_deg = 0.2;
  EXPECT_EQ(readout(tight, 0.0, 0.0, 0.3), Words{"turn 1\xC2\xB0 right"});
  // Facing the wrong way entirely: half a turn.
  EXPECT_EQ(readout(g, 0.0, 0.0, 180.0), Words{"turn 180\xC2\xB0 right"});
}

TEST(ParkingReadout, EitherDirectionTurnsToTheNearerHeading) {
  Goal g = readoutGoal();
  g.either_direction = true;
  EXPECT_EQ(readout(g, 0.0, 0.0, 180.0), Words{});
  EXPECT_EQ(readout(g, 0.0, 0.0, 170.0), Words{"turn 10\xC2\xB0 left"});
  EXPECT_EQ(readout(g, 0.0, 0.0, -170.0), Words{"turn 10\xC2\xB0 right"});
  EXPECT_EQ(readout(g, 0.0, 0.0, 15.0), Words{"turn 15\xC2\xB0 right"});
  // A quarter turn off is as far from either; it still names a way.
  EXPECT_EQ(readout(g, 0.0, 0.0, 90.0).size(), 1u);
}

TEST(ParkingReadout, StopOnlyOncePositionAndHeadingHold) {
  const Goal g = readoutGoal();
  EXPECT_EQ(readout(g, 0.0, 0.0, 0.0, 0.31), Words{"stop"});
  EXPECT_EQ(readout(g, 0.0, 0.0, 0.0, -1.5), Words{"stop"});
  EXPECT_EQ(readout(g, 0.0, 0.0, 0.0, 0.3), Words{});  // on the limit counts as stopped
  // Still rolling towards the bay: "stop" would contradict "forward".
  EXPECT_EQ(readout(g, 0.9, 0.0, 0.0, 1.0), Words{"0.9 m forward"});
  EXPECT_EQ(readout(g, 0.0, 0.0, 10.0, 1.0), Words{"turn 10\xC2\xB0 right"});
}

TEST(ParkingReadout, NothingWithinTheTolerances) {
  const Goal g = readoutGoal();
  EXPECT_EQ(readout(g, 0.0, 0.0), Words{});
  EXPECT_EQ(readout(g, 0.3, 0.39, 7.9, 0.29), Words{});  // 0.49 m, 7.9 degrees
  // Just outside by position: the components that matter, to a tenth.
  EXPECT_EQ(readout(g, 0.51, 0.0), Words{"0.5 m forward"});
  // A component under 5 cm reads "0.0 m": not listed.
  EXPECT_EQ(readout(g, 0.7, 0.04), Words{"0.7 m forward"});
}

TEST(ParkingReadout, FarAwayIsOneDistance) {
  const Goal g = readoutGoal();
  EXPECT_DOUBLE_EQ(nearBayDistance(g), 6.0);
  const std::vector<ParkingFix> far =
      parkingFixes(g, g.bay.center + Eigen::Vector2d(12.0, 5.0), unitFromDegrees(0.0), 4.0);
  ASSERT_EQ(far.size(), 1u);
  EXPECT_EQ(far[0].kind, Kind::kToBay);
  EXPECT_DOUBLE_EQ(far[0].amount, 13.0);
  EXPECT_EQ(fixText(far[0]), "13.0 m to the bay");
  // At the near distance the readout speaks in the car's terms.
  EXPECT_EQ(readout(g, 6.0, 0.0), Words{"6.0 m forward"});
  EXPECT_EQ(readout(g, 6.01, 0.0), Words{"6.0 m to the bay"});
}

TEST(ParkingReadout, FixesAreEmptyExactlyWhenTheCheckPasses) {
  // Seeded random poses around the bay, tolerances varied: the readout is empty exactly when
  // checkParking passes, every amount is non-negative and the kinds keep the driver's order.
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> offset(-1.5, 1.5), turn(-30.0, 30.0), speed(-0.6, 0.6),
      tolerance(0.05, 1.0), heading(-180.0, 180.0);
  int passing = 0;
  for (int i = 0; i < 20000; ++i) {
    Goal g = readoutGoal();
    g.bay.heading_deg = heading(rng);
    g.position_tolerance = tolerance(rng);
    g.either_direction = i % 3 == 0;
    const Eigen::Vector2d position = g.bay.center + Eigen::Vector2d(offset(rng), offset(rng));
    const double car_heading = g.bay.heading_deg + turn(rng) + (i % 6 == 0 ? 180.0 : 0.0);
    const double v = speed(rng);
    const ParkingCheck check = checkParking(g, position, unitFromDegrees(car_heading), v);
    const std::vector<ParkingFix> fixes = parkingFixes(g, check);
    ASSERT_EQ(fixes.empty(), check.parked()) << i;
    passing += check.parked() ? 1 : 0;
    for (std::size_t k = 0; k < fixes.size(); ++k) {
      EXPECT_GE(fixes[k].amount, 0.0) << i;
      if (k > 0) {
        EXPECT_LT(fixes[k - 1].kind, fixes[k].kind) << i;
      }
    }
  }
  EXPECT_GT(passing, 100) << "the random poses never passed: the test shows little";
}

TEST(ParkingReadout, StarsNameWhatWasEarnedOrMissed) {
  Goal g = readoutGoal();
  g.par_time = 12.0;
  const auto texts = [&](const ParkingScore& s) {
    std::string out;
    for (const StarReason& r : starReasons(g, s)) {
      out += std::string(r.earned ? "+" : "-") + r.text + ";";
    }
    return out;
  };
  EXPECT_EQ(texts({1200, 10.0, 0, 3}), "+parked;+no damage;+within par 12.0 s;");
  EXPECT_EQ(texts({1440, 12.0, 0, 3}), "+parked;+no damage;+within par 12.0 s;");
  EXPECT_EQ(texts({1824, 15.2, 6, 1}), "+parked;-6 damage;-over par by 3.2 s;");
  EXPECT_EQ(texts({1445, 12.04, 0, 2}), "+parked;+no damage;-over par by 0.1 s;");
  g.par_time.reset();
  EXPECT_EQ(texts({99999, 999.0, 0, 3}), "+parked;+no damage;+no par time;");
  // The earned stars are the score's stars.
  g.par_time = 12.0;
  for (const double seconds : {3.0, 12.0, 12.01, 40.0}) {
    for (const int damage : {0, 1, 30}) {
      int earned = 0;
      for (const StarReason& r : starReasons(g, {0, seconds, damage, 0})) earned += r.earned;
      EXPECT_EQ(earned, starsFor(g, seconds, damage)) << seconds << " " << damage;
    }
  }
}

// A car 4 m before a bay facing +x: the challenge's reasons follow the run.
TEST(ParkingReadout, NotParkedReasonsFollowTheRun) {
  Scene scene = test::sceneWith({});
  Goal g;
  g.bay.center = {4.0, 0.0};
  g.time_limit = 1.0;
  scene.goal = g;
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  EXPECT_EQ(notParkedReasons(c), Words{"4.0 m forward"});
  EXPECT_EQ(bayReadout(c), Words{"4.0 m forward"});
  while (!c.over()) {
    world.step(InputFrame{true, false, false, false});
    c.observe(world);
  }
  ASSERT_TRUE(c.timedOut());
  const Words reasons = notParkedReasons(c);
  ASSERT_GE(reasons.size(), 2u);
  EXPECT_EQ(reasons.front(), "time up");
  EXPECT_EQ(bayReadout(c), Words{}) << "the run is over";

  // At rest in the bay: the hold, then parked (no reasons).
  scene.goal->bay.center = {0.0, 0.0};
  World still(scene);
  ParkingChallenge d(*scene.goal, 120.0, 100);
  d.observe(still);
  EXPECT_EQ(notParkedReasons(d), Words{"hold 0.0 / 0.5 s"});
  EXPECT_EQ(bayReadout(d), Words{});
  while (!d.over()) {
    still.step(InputFrame{});
    d.observe(still);
  }
  EXPECT_EQ(notParkedReasons(d), Words{});

  // Far from the bay: the distance.
  scene.goal->bay.center = {40.0, 0.0};
  const World far(scene);
  ParkingChallenge e(*scene.goal, 120.0, 100);
  e.observe(far);
  EXPECT_EQ(notParkedReasons(e), Words{"40.0 m to the bay"});
  EXPECT_EQ(bayReadout(e), Words{});
}

// A chain of two bays says which bay is next until the last is parked.
TEST(ParkingReadout, AChainNamesTheNextBay) {
  Scene scene = test::sceneWith({});
  Goal g;
  g.bay.center = {0.0, 0.0};
  ParkingBay second = g.bay;
  second.center = {30.0, 0.0};
  g.next_bays = {second};
  g.time_limit = 2.0;
  scene.goal = g;
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  EXPECT_EQ(nextBayText(c), "next bay 1/2");
  EXPECT_EQ(notParkedReasons(c), (Words{"next bay 1/2", "hold 0.0 / 0.5 s"}));
  while (c.baysParked() == 0) {
    world.step(InputFrame{});
    c.observe(world);
  }
  EXPECT_EQ(nextBayText(c), "next bay 2/2");
  EXPECT_EQ(notParkedReasons(c), (Words{"next bay 2/2", "30.0 m to the bay"}));
  while (!c.over()) {
    world.step(InputFrame{true, false, false, false});
    c.observe(world);
  }
  ASSERT_TRUE(c.timedOut());
  const Words reasons = notParkedReasons(c);
  ASSERT_GE(reasons.size(), 3u);
  EXPECT_EQ(reasons[0], "time up");
  EXPECT_EQ(reasons[1], "next bay 2/2");

  // One bay: no bay number anywhere.
  scene.goal->next_bays.clear();
  const World one(scene);
  ParkingChallenge d(*scene.goal, 120.0, 100);
  d.observe(one);
  EXPECT_EQ(nextBayText(d), "");
  EXPECT_EQ(notParkedReasons(d), Words{"hold 0.0 / 0.5 s"});
}

}  // namespace
}  // namespace cardemo
