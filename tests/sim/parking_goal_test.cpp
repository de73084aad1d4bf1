#include "sim/parking_goal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "geometry/angle.hpp"
#include "scene_builders.hpp"
#include "sim/state_hash.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

// Bay at (10, 5) facing +y (heading 90), tolerances 0.5 m, 8 degrees, 0.3 m/s.
Goal bayGoal() {
  Goal g;
  g.bay.center = {10.0, 5.0};
  g.bay.heading_deg = 90.0;
  g.position_tolerance = 0.5;
  g.heading_tolerance_deg = 8.0;
  g.max_speed = 0.3;
  return g;
}

ParkingCheck at(const Goal& g, double dx, double dy, double heading_deg, double speed) {
  return checkParking(g, g.bay.center + Eigen::Vector2d(dx, dy), unitFromDegrees(heading_deg),
                      speed);
}

TEST(ParkingCheck, CentredAlignedAndStoppedIsParked) {
  const ParkingCheck c = at(bayGoal(), 0, 0, 90, 0);
  EXPECT_TRUE(c.parked());
  EXPECT_EQ(c.distance, 0.0);
  EXPECT_EQ(c.heading_error_deg, 0.0);
}

TEST(ParkingCheck, PositionJustInsideAndJustOutsideTheTolerance) {
  const Goal g = bayGoal();
  EXPECT_TRUE(at(g, 0.5, 0, 90, 0).position_ok);  // exactly on the tolerance counts
  EXPECT_TRUE(at(g, 0, -0.4999, 90, 0).parked());
  EXPECT_FALSE(at(g, 0.5001, 0, 90, 0).position_ok);
  EXPECT_FALSE(at(g, 0.3, 0.4001, 90, 0).parked());  // 0.50008 m diagonally
  EXPECT_TRUE(at(g, 0.3, 0.3999, 90, 0).parked());   // 0.49992 m
}

TEST(ParkingCheck, HeadingJustInsideAndJustOutsideTheTolerance) {
  const Goal g = bayGoal();
  EXPECT_TRUE(at(g, 0, 0, 90 + 7.99, 0).parked());
  EXPECT_TRUE(at(g, 0, 0, 90 - 7.99, 0).parked());
  EXPECT_FALSE(at(g, 0, 0, 90 + 8.01, 0).heading_ok);
  EXPECT_FALSE(at(g, 0, 0, 90 - 8.01, 0).parked());
  EXPECT_NEAR(at(g, 0, 0, 95, 0).heading_error_deg, 5.0, 1e-12);
}

TEST(ParkingCheck, HeadingErrorWrapsAcross180) {
  Goal g = bayGoal();
  g.bay.heading_deg = 180.0;
  EXPECT_TRUE(at(g, 0, 0, -176, 0).parked());
  EXPECT_NEAR(at(g, 0, 0, -176, 0).heading_error_deg, 4.0, 1e-12);
}

TEST(ParkingCheck, ReverseParkedCountsOnlyWhenEitherDirection) {
  Goal g = bayGoal();
  EXPECT_FALSE(at(g, 0, 0, -90, 0).parked());
  EXPECT_NEAR(at(g, 0, 0, -90, 0).heading_error_deg, 180.0, 1e-12);
  g.either_direction = true;
  EXPECT_TRUE(at(g, 0, 0, -90, 0).parked());
  EXPECT_EQ(at(g, 0, 0, -90, 0).heading_error_deg, 0.0);
  EXPECT_TRUE(at(g, 0, 0, -90 + 7.99, 0).parked());
  EXPECT_FALSE(at(g, 0, 0, -90 + 8.01, 0).parked());
  EXPECT_FALSE(at(g, 0, 0, 0, 0).parked());  // across the bay: 90 degrees off either way
  EXPECT_NEAR(at(g, 0, 0, 0, 0).heading_error_deg, 90.0, 1e-12);
}

TEST(ParkingCheck, SpeedJustAboveTheLimitIsNotParked) {
  const Goal g = bayGoal();
  EXPECT_TRUE(at(g, 0, 0, 90, 0.3).parked());
  EXPECT_TRUE(at(g, 0, 0, 90, -0.3).parked());
  EXPECT_FALSE(at(g, 0, 0, 90, 0.3001).parked());
  EXPECT_FALSE(at(g, 0, 0, 90, -0.3001).speed_ok);
}

TEST(ParkingScore, StarsForDamageAndPar) {
  Goal g = bayGoal();
  g.par_time = 20.0;
  EXPECT_EQ(starsFor(g, 20.0, 0), 3);  // exactly on par counts
  EXPECT_EQ(starsFor(g, 20.01, 0), 2);
  EXPECT_EQ(starsFor(g, 10.0, 5), 2);
  EXPECT_EQ(starsFor(g, 30.0, 5), 1);
  g.par_time.reset();
  EXPECT_EQ(starsFor(g, 1000.0, 0), 3);  // no par: the time star is free
  EXPECT_EQ(starsFor(g, 1000.0, 1), 2);
}

TEST(ParkingScore, BetterMeansMoreStarsThenLessTimeThenLessDamage) {
  const ParkingScore three{1200, 10.0, 0, 3};
  const ParkingScore two_fast{600, 5.0, 10, 2};
  EXPECT_TRUE(three.betterThan(two_fast));
  EXPECT_FALSE(two_fast.betterThan(three));
  const ParkingScore three_faster{1000, 8.0, 0, 3};
  EXPECT_TRUE(three_faster.betterThan(three));
  const ParkingScore same_time_less_damage{1200, 10.0, 0, 2};
  const ParkingScore same_time_more_damage{1200, 10.0, 4, 2};
  EXPECT_TRUE(same_time_less_damage.betterThan(same_time_more_damage));
  EXPECT_FALSE(three.betterThan(three));
}

TEST(ParkingScore, LimitFramesRoundsUp) {
  Goal g = bayGoal();
  EXPECT_FALSE(limitFrames(g, 120.0).has_value());
  g.time_limit = 60.0;
  EXPECT_EQ(limitFrames(g, 120.0), 7200);
  g.time_limit = 0.001;
  EXPECT_EQ(limitFrames(g, 120.0), 1);
}

TEST(ParkingScore, HoldFramesRoundUpAndZeroMeansAtOnce) {
  Goal g = bayGoal();
  EXPECT_EQ(holdFrames(g, 120.0), 60);  // the default 0.5 s
  g.hold_time = 0.0;
  EXPECT_EQ(holdFrames(g, 120.0), 0);
  g.hold_time = 0.001;
  EXPECT_EQ(holdFrames(g, 120.0), 1);
  g.hold_time = 0.25;
  EXPECT_EQ(holdFrames(g, 60.0), 15);
}

// A car that starts at rest 4 m before a bay, drives towards it and brakes: it parks once the
// checks have held for the hold time; the World's hash is unaffected.
Scene driveInScene() {
  Scene s = test::sceneWith({}, 0.0, 0.0, 0.0);
  Goal g;
  g.bay.center = {4.0, 0.0};
  g.bay.heading_deg = 0.0;
  g.position_tolerance = 0.5;
  g.max_speed = 0.3;
  g.par_time = 10.0;
  s.goal = g;
  return s;
}

InputFrame driveIn(const World& world) {
  InputFrame in;
  in.up = world.car().position.x() < 2.5;
  in.down = !in.up && world.car().speed > 0.0;
  return in;
}

// Runs `scene` with `drive` until the challenge is over (or `frames` steps) and checks that it
// parks where an independent count of consecutive passing checks reaches the hold frames.
void expectParksAfterTheHold(const Scene& scene,
                             const std::function<InputFrame(const World&)>& drive, int frames,
                             std::int64_t* parked_at = nullptr) {
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  const std::int64_t hold = holdFrames(*scene.goal, world.settings().hz);
  std::int64_t run_start = -1;
  std::int64_t expected = -1;
  const auto count = [&] {
    const ParkingCheck c =
        checkParking(*scene.goal, world.car().position, world.car().direction, world.car().speed);
    if (!c.parked())
      run_start = -1;
    else if (run_start < 0)
      run_start = world.frame();
    if (expected < 0 && run_start >= 0 && world.frame() - run_start >= hold) {
      expected = world.frame();
    }
  };
  count();
  challenge.observe(world);
  for (int i = 0; i < frames && !challenge.over(); ++i) {
    world.step(drive(world));
    count();
    challenge.observe(world);
  }
  ASSERT_GE(expected, 0) << "the script never parks";
  ASSERT_TRUE(challenge.parkedFrame().has_value());
  EXPECT_EQ(*challenge.parkedFrame(), expected);
  ASSERT_TRUE(challenge.score().has_value());
  // The score counts from the clock's start: the last frame before the car first moved.
  EXPECT_EQ(challenge.score()->frames, expected - challenge.clockStart().value_or(expected));
  EXPECT_EQ(challenge.frame(), expected);
  if (parked_at != nullptr) *parked_at = expected;
}

TEST(ParkingChallenge, ParksOnceTheChecksHeldForTheHoldTime) {
  const Scene scene = driveInScene();
  std::int64_t parked = 0;
  expectParksAfterTheHold(scene, driveIn, 2400, &parked);
  // The same drive with no hold parks 60 frames (0.5 s at 120 Hz) earlier: the car stays put.
  Scene at_once = scene;
  at_once.goal->hold_time = 0.0;
  std::int64_t immediate = 0;
  expectParksAfterTheHold(at_once, driveIn, 2400, &immediate);
  EXPECT_EQ(parked, immediate + 60);
}

TEST(ParkingChallenge, ScoreAndTimerStopAtTheParkedFrame) {
  const Scene scene = driveInScene();
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  challenge.observe(world);
  while (!challenge.over() && world.frame() < 2400) {
    world.step(driveIn(world));
    challenge.observe(world);
  }
  ASSERT_TRUE(challenge.parkedFrame().has_value());
  const std::int64_t parked = *challenge.parkedFrame();
  EXPECT_EQ(challenge.score()->damage, 0);
  EXPECT_EQ(challenge.score()->stars, 3);
  EXPECT_DOUBLE_EQ(challenge.heldSeconds(), 0.5);
  // Observing more frames changes nothing once parked.
  world.step(InputFrame{true, false, false, false});
  challenge.observe(world);
  EXPECT_EQ(challenge.frame(), parked);
  EXPECT_EQ(challenge.clockStart(), 0);  // the throttle was held from frame 0
  EXPECT_EQ(challenge.seconds(), static_cast<double>(parked) / 120.0);
}

TEST(ParkingChallenge, StartingInTheBayAtRestParksAfterTheHold) {
  Scene scene = driveInScene();
  scene.goal->bay.center = {0.0, 0.0};
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  EXPECT_FALSE(challenge.parkedFrame().has_value());
  EXPECT_EQ(challenge.holdStart(), 0);
  for (int i = 0; i < 59; ++i) {
    world.step(InputFrame{});
    challenge.observe(world);
  }
  EXPECT_FALSE(challenge.over());
  EXPECT_NEAR(challenge.heldSeconds(), 59.0 / 120.0, 1e-12);
  world.step(InputFrame{});
  challenge.observe(world);
  EXPECT_EQ(challenge.parkedFrame(), 60);
  // The car never moved, so the level clock never started: 0 s.
  EXPECT_FALSE(challenge.clockStart().has_value());
  EXPECT_EQ(challenge.score()->frames, 0);
  EXPECT_EQ(challenge.score()->seconds, 0.0);

  scene.goal->hold_time = 0.0;
  const World again(scene);
  ParkingChallenge at_once(*scene.goal, 120.0, 100);
  at_once.observe(again);
  EXPECT_EQ(at_once.parkedFrame(), 0);
}

// The play-test's complaint: a car passing through the bay below the speed limit for a moment
// (here pulling away from rest inside it) must not count as parked.
TEST(ParkingChallenge, PullingAwayThroughTheBayIsNotParked) {
  Scene scene = driveInScene();
  scene.goal->bay.center = {0.45, 0.0};  // the car starts inside the position tolerance
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  int passing = 0;
  for (int i = 0; i < 240; ++i) {
    world.step(InputFrame{true, false, false, false});
    challenge.observe(world);
    if (challenge.lastCheck().parked()) ++passing;
  }
  EXPECT_GT(passing, 0) << "the checks never passed: the test shows nothing";
  EXPECT_FALSE(challenge.parkedFrame().has_value());
  EXPECT_FALSE(challenge.holdStart().has_value());
  EXPECT_EQ(challenge.heldSeconds(), 0.0);
}

// A hold broken by a frame outside the checks starts again from zero.
TEST(ParkingChallenge, ABrokenHoldStartsAgain) {
  Scene scene = driveInScene();
  scene.goal->bay.center = {0.0, 0.0};
  int frame = 0;
  bool broken = false;
  // 30 frames at rest in the bay, a push of 30 frames (faster than max_speed), then braking to a
  // stop.
  const auto drive = [&](const World& world) {
    ++frame;
    broken = broken || std::abs(world.car().speed) > scene.goal->max_speed;
    InputFrame in;
    in.up = frame > 30 && frame <= 60;
    in.down = frame > 60 && world.car().speed > 0.0;
    return in;
  };
  std::int64_t parked = 0;
  expectParksAfterTheHold(scene, drive, 2400, &parked);
  EXPECT_TRUE(broken) << "the push never broke the hold: the test shows nothing";
  EXPECT_GT(parked, 120);  // not at 60: the hold restarted after the push
}

// The time limit counts on the level clock: from the last frame before the car first moved.
TEST(ParkingChallenge, TimeLimitEndsTheRunOnTheLevelClock) {
  Scene scene = driveInScene();
  scene.goal->bay.center = {40.0, 0.0};  // out of reach in the time
  scene.goal->time_limit = 0.5;          // 60 frames at 120 Hz
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  for (int i = 0; i < 300; ++i) {  // 2.5 s at a standstill: the clock does not run
    world.step(InputFrame{});
    challenge.observe(world);
  }
  EXPECT_FALSE(challenge.over());
  EXPECT_EQ(challenge.seconds(), 0.0);
  while (!challenge.over()) {
    world.step(InputFrame{true, false, false, false});
    challenge.observe(world);
  }
  EXPECT_TRUE(challenge.timedOut());
  EXPECT_FALSE(challenge.parkedFrame().has_value());
  EXPECT_EQ(challenge.clockStart(), 300);
  EXPECT_EQ(challenge.clockFrames(), 60);
  EXPECT_EQ(world.frame(), 360);
}

// What starts the clock: the first step that moves the car, whatever key did it; steering at a
// standstill moves nothing and starts nothing.
TEST(ParkingChallenge, ClockStartsAtTheFirstStepThatMovesTheCar) {
  const Scene scene = driveInScene();
  struct Case {
    const char* what;
    InputFrame keys;
  };
  for (const Case& c : {Case{"throttle", {true, false, false, false}},
                        Case{"reverse from a standstill", {false, true, false, false}},
                        Case{"throttle while steering", {true, false, true, false}}}) {
    World world(scene);
    ParkingChallenge challenge(*scene.goal, 120.0, 100);
    challenge.observe(world);
    for (const InputFrame& still :
         {InputFrame{}, InputFrame{false, false, true, false},
          InputFrame{false, false, false, true}, InputFrame{false, false, false, false, true}}) {
      for (int i = 0; i < 50; ++i) {  // nothing, steering left, steering right, the handbrake
        world.step(still);
        challenge.observe(world);
      }
    }
    EXPECT_EQ(world.car().position, scene.player.position) << c.what;
    EXPECT_FALSE(challenge.clockStart().has_value()) << c.what;
    world.step(c.keys);
    challenge.observe(world);
    ASSERT_NE(world.car().position, scene.player.position) << c.what << ": the car did not move";
    EXPECT_EQ(challenge.clockStart(), 200) << c.what;
    EXPECT_EQ(challenge.clockFrames(), 1) << c.what;
  }
}

// A player who reads the task for 2 s before driving parks with the same time as one who drives
// at once: the same drive, shifted, gives the same score.
TEST(ParkingChallenge, WaitingBeforeDrivingCostsNoTime) {
  const Scene scene = driveInScene();
  std::optional<ParkingScore> scores[2];
  for (const int wait : {0, 240}) {
    World world(scene);
    ParkingChallenge challenge(*scene.goal, 120.0, 100);
    challenge.observe(world);
    for (int i = 0; i < wait; ++i) {
      world.step(InputFrame{});
      challenge.observe(world);
    }
    while (!challenge.over() && world.frame() < 4000) {
      world.step(driveIn(world));
      challenge.observe(world);
    }
    ASSERT_TRUE(challenge.parkedFrame().has_value()) << wait;
    EXPECT_EQ(challenge.clockStart(), wait);
    scores[wait == 0 ? 0 : 1] = challenge.score();
  }
  EXPECT_EQ(scores[0]->frames, scores[1]->frames);
  EXPECT_EQ(scores[0]->seconds, scores[1]->seconds);
  EXPECT_EQ(scores[0]->stars, scores[1]->stars);
}

TEST(ParkingChallenge, RollingThroughTheBayTooFastIsNotParked) {
  Scene scene = driveInScene();
  scene.player.speed = 5.0;
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  for (int i = 0; i < 240; ++i) {
    world.step(InputFrame{});
    challenge.observe(world);
  }
  EXPECT_GT(world.car().position.x(), 5.0);  // went past the bay
  EXPECT_FALSE(challenge.parkedFrame().has_value());
}

// A chain of two bays on the x axis, A 4 m and B 12 m ahead of a car at rest at the origin.
Scene chainScene() {
  Scene s = driveInScene();
  ParkingBay b = s.goal->bay;
  b.center = {12.0, 0.0};
  s.goal->next_bays = {b};
  return s;
}

// Drives at up to 3 m/s and brakes 0.5 m before `x` (where it stops).
InputFrame driveTo(const World& world, double x) {
  InputFrame in;
  const bool short_of = world.car().position.x() < x - 0.5;
  in.up = short_of && world.car().speed < 3.0;
  in.down = !short_of && world.car().speed > 0.0;
  return in;
}

// Drives to bay A, stops there until it counts, then drives on to bay B and stops.
InputFrame driveChain(const World& world, const ParkingChallenge& challenge) {
  return driveTo(world, challenge.baysParked() == 0 ? 4.0 : 12.0);
}

TEST(ParkingChallenge, AChainParksEachBayInTurnAfterItsOwnHold) {
  const Scene scene = chainScene();
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  ASSERT_EQ(challenge.bays().size(), 2u);
  EXPECT_EQ(challenge.bays()[1].center, Eigen::Vector2d(12.0, 0.0));
  const std::int64_t hold = holdFrames(*scene.goal, world.settings().hz);
  // An independent count of the rule: the checks against the bay of the moment, held unbroken
  // for the hold; the second bay's run can start only after the first bay counted.
  std::size_t bay = 0;
  std::int64_t run_start = -1;
  std::vector<std::int64_t> expected;
  const auto count = [&] {
    Goal g = *scene.goal;
    g.bay = bay == 0 ? scene.goal->bay : scene.goal->next_bays[0];
    const ParkingCheck c =
        checkParking(g, world.car().position, world.car().direction, world.car().speed);
    if (!c.parked()) {
      run_start = -1;
    } else if (run_start < 0) {
      run_start = world.frame();
    }
    if (run_start >= 0 && world.frame() - run_start >= hold) {
      expected.push_back(world.frame());
      ++bay;
      run_start = -1;
    }
  };
  count();
  challenge.observe(world);
  for (int i = 0; i < 4800 && !challenge.over(); ++i) {
    world.step(driveChain(world, challenge));
    if (bay < 2) count();
    challenge.observe(world);
    EXPECT_EQ(challenge.baysParked(), expected.size()) << "frame " << world.frame();
    if (challenge.baysParked() == 1 && !challenge.over()) {
      EXPECT_EQ(challenge.currentBay(), 1u);
      EXPECT_EQ(challenge.goal().bay.center, Eigen::Vector2d(12.0, 0.0));
    }
  }
  ASSERT_EQ(expected.size(), 2u) << "the script never parks in both bays";
  EXPECT_EQ(challenge.bayParkedFrame(0), expected[0]);
  EXPECT_EQ(challenge.bayParkedFrame(1), expected[1]);
  EXPECT_FALSE(challenge.bayParkedFrame(2).has_value());
  EXPECT_EQ(challenge.parkedFrame(), expected[1]);
  EXPECT_GT(expected[1] - expected[0], hold) << "the second hold starts after the first bay";
  ASSERT_TRUE(challenge.score().has_value());
  EXPECT_EQ(challenge.score()->frames, expected[1] - challenge.clockStart().value_or(0));
  EXPECT_EQ(challenge.currentBay(), 1u);  // the last bay stays current once parked
}

TEST(ParkingChallenge, AChainsLaterBayDoesNotCountBeforeItsTurn) {
  // Straight past bay A and into bay B: B is not the bay yet, so nothing counts.
  const Scene scene = chainScene();
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  int in_b = 0;
  for (int i = 0; i < 2400 && !challenge.over(); ++i) {
    world.step(driveTo(world, 12.0));
    challenge.observe(world);
    Goal b = *scene.goal;
    b.bay = scene.goal->next_bays[0];
    in_b += checkParking(b, world.car().position, world.car().direction, world.car().speed).parked()
                ? 1
                : 0;
  }
  EXPECT_GT(in_b, 600) << "the car never stood in bay B: the test shows nothing";
  EXPECT_FALSE(challenge.over());
  EXPECT_EQ(challenge.baysParked(), 0u);
  EXPECT_EQ(challenge.currentBay(), 0u);
  EXPECT_FALSE(challenge.lastCheck().position_ok);  // judged against bay A, 8 m back
}

TEST(ParkingChallenge, AChainRunsOutOfTimeBetweenBays) {
  Scene scene = chainScene();
  scene.goal->time_limit = 4.0;
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  challenge.observe(world);
  // Park in bay A, then wait there until the time is up.
  while (!challenge.over()) {
    world.step(challenge.baysParked() == 0 ? driveIn(world) : InputFrame{});
    challenge.observe(world);
  }
  EXPECT_TRUE(challenge.timedOut());
  EXPECT_EQ(challenge.baysParked(), 1u);
  EXPECT_FALSE(challenge.parkedFrame().has_value());
  EXPECT_FALSE(challenge.score().has_value());
}

TEST(ParkingChallenge, OneBayIsAChainOfOne) {
  const Scene scene = driveInScene();
  World world(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  ASSERT_EQ(challenge.bays().size(), 1u);
  EXPECT_EQ(challenge.bays()[0].center, scene.goal->bay.center);
  challenge.observe(world);
  while (!challenge.over() && world.frame() < 2400) {
    world.step(driveIn(world));
    challenge.observe(world);
  }
  ASSERT_TRUE(challenge.parkedFrame().has_value());
  EXPECT_EQ(challenge.baysParked(), 1u);
  EXPECT_EQ(challenge.bayParkedFrame(0), challenge.parkedFrame());
  EXPECT_EQ(challenge.currentBay(), 0u);
  EXPECT_EQ(goalBays(*scene.goal).size(), 1u);
}

TEST(ParkingChallenge, ObservingDoesNotChangeTheWorldHash) {
  const Scene scene = driveInScene();
  World watched(scene);
  World alone(scene);
  ParkingChallenge challenge(*scene.goal, 120.0, 100);
  const std::vector<InputFrame> drive = test::scriptedDrive(7, 600);
  for (const InputFrame& in : drive) {
    watched.step(in);
    challenge.observe(watched);
    alone.step(in);
  }
  EXPECT_EQ(watched.stateHash(), alone.stateHash());
}

}  // namespace
}  // namespace cardemo
