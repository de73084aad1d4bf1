// The pedal rule (a press that began against the motion brakes and holds; reverse and drive need a
// fresh press), the gear, and the keyboard steering ramp, through World as the game steps it.

#include "sim/driver_controls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::sceneWith;
using testing::kDown;
using testing::kHandbrake;
using testing::kLeft;
using testing::kNone;
using testing::kRight;
using testing::kUp;

constexpr InputFrame kBothPedals{true, true, false, false};
constexpr InputFrame kDownHandbrake{false, true, false, false, true};
constexpr InputFrame kDownLeft{false, true, true, false};

// A world in an empty scene whose car starts at `speed` (m/s, negative: backwards).
World rollingWorld(double speed) {
  Scene scene = sceneWith({});
  scene.player.speed = speed;
  return World(std::move(scene));
}

void holdKeys(World& world, const InputFrame& in, int frames) {
  for (int f = 0; f < frames; ++f) world.step(in);
}

// Steps with `in` until the car stands (at most 10 s); returns the frames it took.
int holdUntilStopped(World& world, const InputFrame& in) {
  int frames = 0;
  while (world.car().speed != 0.0 && frames < 1200) {
    world.step(in);
    ++frames;
  }
  return frames;
}

double toDegrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

TEST(PedalRule, DownHeldThroughTheStopHoldsTheCar) {
  World world = rollingWorld(5.0);
  ASSERT_GT(holdUntilStopped(world, kDown), 0);
  ASSERT_LT(world.frame(), 1200);
  EXPECT_EQ(world.controls().down, PedalPress::kBrakes);
  const Eigen::Vector2d stopped_at = world.car().position;
  for (int f = 0; f < 600; ++f) {
    world.step(kDown);
    ASSERT_EQ(world.car().speed, 0.0) << "frame " << f << " after the stop";
    ASSERT_EQ(world.gear(), Gear::kNeutral);
  }
  EXPECT_EQ(world.car().position, stopped_at);
  EXPECT_FALSE(world.reversing());
}

TEST(PedalRule, ReleaseThenPressAtAStandstillReverses) {
  World world = rollingWorld(5.0);
  holdUntilStopped(world, kDown);
  holdKeys(world, kDown, 30);
  world.step(kNone);  // one frame released is enough
  EXPECT_EQ(world.controls().down, PedalPress::kReleased);
  EXPECT_EQ(world.gear(), Gear::kNeutral);
  world.step(kDown);
  EXPECT_EQ(world.controls().down, PedalPress::kDrives);
  EXPECT_LT(world.car().speed, 0.0);
  EXPECT_EQ(world.gear(), Gear::kReverse);
  holdKeys(world, kDown, 120);
  EXPECT_LT(world.car().speed, -1.0);
}

TEST(PedalRule, DownPressedAtAStandstillReversesAtOnce) {
  World world = rollingWorld(0.0);
  EXPECT_EQ(world.gear(), Gear::kNeutral);
  world.step(kDown);
  EXPECT_LT(world.car().speed, 0.0);
  EXPECT_EQ(world.gear(), Gear::kReverse);
  // Still one press: it keeps driving backwards.
  holdKeys(world, kDown, 60);
  EXPECT_LT(world.car().speed, -1.0);
}

TEST(PedalRule, DownPressedWhileRollingBackwardsDrivesBackwards) {
  World world = rollingWorld(-2.0);
  world.step(kDown);
  EXPECT_EQ(world.controls().down, PedalPress::kDrives);
  EXPECT_LT(world.car().speed, -2.0);
}

TEST(PedalRule, UpOutOfReverseIsSymmetric) {
  World world = rollingWorld(-4.0);
  ASSERT_GT(holdUntilStopped(world, kUp), 0);
  EXPECT_EQ(world.controls().up, PedalPress::kBrakes);
  for (int f = 0; f < 600; ++f) {
    world.step(kUp);
    ASSERT_EQ(world.car().speed, 0.0) << "frame " << f << " after the stop";
  }
  EXPECT_EQ(world.gear(), Gear::kNeutral);
  world.step(kNone);
  world.step(kUp);
  EXPECT_GT(world.car().speed, 0.0);
  EXPECT_EQ(world.gear(), Gear::kDrive);

  World still = rollingWorld(0.0);
  still.step(kUp);  // a press that begins at a standstill drives at once
  EXPECT_GT(still.car().speed, 0.0);
}

TEST(PedalRule, BothPedalsBrakeAndHoldAndTheOneLeftKeepsItsKind) {
  // Driving forward, Down joins the throttle: both brake to a stop and hold.
  World world = rollingWorld(0.0);
  holdKeys(world, kUp, 120);
  holdUntilStopped(world, kBothPedals);
  holdKeys(world, kBothPedals, 120);
  EXPECT_EQ(world.car().speed, 0.0);
  EXPECT_EQ(world.gear(), Gear::kNeutral);
  // Up let go, Down still held: its press began while moving forward, so it only holds.
  holdKeys(world, kDown, 120);
  EXPECT_EQ(world.car().speed, 0.0);
  // Up still held, Down let go: Up's press began while moving forward, so it drives.
  World other = rollingWorld(0.0);
  holdKeys(other, kUp, 120);
  holdUntilStopped(other, kBothPedals);
  other.step(kUp);
  EXPECT_GT(other.car().speed, 0.0);
  // Both pressed together at a standstill hold the car; Up alone then drives (its press began at a
  // standstill), Down alone reverses.
  World pressed = rollingWorld(0.0);
  holdKeys(pressed, kBothPedals, 60);
  EXPECT_EQ(pressed.car().speed, 0.0);
  EXPECT_EQ(pressed.gear(), Gear::kNeutral);
  pressed.step(kDown);
  EXPECT_LT(pressed.car().speed, 0.0);
}

TEST(PedalRule, HandbrakeHoldsWhateverThePedalAndThePressKeepsItsKind) {
  // Moving forward, handbrake and Down: stopped; the handbrake let go, Down still only holds.
  World world = rollingWorld(5.0);
  holdUntilStopped(world, kDownHandbrake);
  EXPECT_EQ(world.controls().down, PedalPress::kBrakes);
  holdKeys(world, kDown, 120);
  EXPECT_EQ(world.car().speed, 0.0);
  // At a standstill, Down pressed under the handbrake is a reversing press: nothing moves until
  // the handbrake is let go, then the car backs away.
  World parked = rollingWorld(0.0);
  holdKeys(parked, kDownHandbrake, 60);
  EXPECT_EQ(parked.car().speed, 0.0);
  EXPECT_EQ(parked.gear(), Gear::kReverse);  // engaged
  parked.step(kDown);
  EXPECT_LT(parked.car().speed, 0.0);
  // The handbrake alone at a standstill: neutral.
  World idle = rollingWorld(0.0);
  idle.step(kHandbrake);
  EXPECT_EQ(idle.gear(), Gear::kNeutral);
}

TEST(PedalRule, GameOverReleasesEveryKey) {
  Scene scene = sceneWith({parkedCar("A", 8.0, 0.0, 90.0)});
  scene.player.health = 1;
  scene.player.speed = 10.0;
  World world(std::move(scene));
  while (!world.gameOver() && world.frame() < 600) world.step(kNone);
  ASSERT_TRUE(world.gameOver());
  holdKeys(world, kDown, 240);
  EXPECT_EQ(world.controls(), DriverControls{});
  EXPECT_EQ(world.car().speed, 0.0);
  EXPECT_EQ(world.gear(), Gear::kNeutral);
}

TEST(PedalRule, TheControlsAreInTheStateHash) {
  // Under the handbrake at a standstill nothing moves either way; only the press differs.
  World held = rollingWorld(0.0);
  World idle = rollingWorld(0.0);
  held.step(kDownHandbrake);
  idle.step(kHandbrake);
  ASSERT_EQ(held.car().position, idle.car().position);
  ASSERT_EQ(held.car().speed, idle.car().speed);
  EXPECT_NE(held.stateHash(), idle.stateHash());
  // And the steering key's hold: at full lock, one more step held changes only the count.
  World a = rollingWorld(0.0);
  World b = rollingWorld(0.0);
  holdKeys(a, kLeft, 240);
  holdKeys(b, kNone, 120);
  holdKeys(b, kLeft, 120);
  ASSERT_EQ(a.car().steer, b.car().steer);
  EXPECT_NE(a.stateHash(), b.stateHash());
}

TEST(Gear, FromTheSpeedAndThePresses) {
  DriverControls none;
  DriverControls up{PedalPress::kDrives, PedalPress::kReleased, 0};
  DriverControls down{PedalPress::kReleased, PedalPress::kDrives, 0};
  DriverControls both{PedalPress::kDrives, PedalPress::kDrives, 0};
  DriverControls holding{PedalPress::kReleased, PedalPress::kBrakes, 0};
  EXPECT_EQ(gearOf(0.0, none), Gear::kNeutral);
  EXPECT_EQ(gearOf(0.0, up), Gear::kDrive);
  EXPECT_EQ(gearOf(0.0, down), Gear::kReverse);
  EXPECT_EQ(gearOf(0.0, both), Gear::kNeutral);
  EXPECT_EQ(gearOf(0.0, holding), Gear::kNeutral);
  for (const DriverControls& c : {none, up, down, both, holding}) {
    EXPECT_EQ(gearOf(0.1, c), Gear::kDrive);
    EXPECT_EQ(gearOf(-0.1, c), Gear::kReverse);
  }
  EXPECT_EQ(gearLetter(Gear::kDrive), 'D');
  EXPECT_EQ(gearLetter(Gear::kReverse), 'R');
  EXPECT_EQ(gearLetter(Gear::kNeutral), 'N');
}

// The wheel angle after holding `in` for `frames` steps from the centre, at rest.
double steerAfterHolding(const InputFrame& in, int frames) {
  World world = rollingWorld(0.0);
  holdKeys(world, in, frames);
  return world.car().steer;
}

TEST(SteeringRamp, ATapOfATenthOfASecondGivesAFewDegrees) {
  const CarParams p;
  const double dt = 1.0 / 120.0;
  // Closed form of the ramp: step k (1-based) turns by (start + accel k dt) dt.
  for (const int frames : {10, 12, 18}) {
    double expected = 0.0;
    for (int k = 1; k <= frames; ++k)
      expected += (p.steer_ramp_start + p.steer_ramp_accel * k * dt) * dt;
    EXPECT_NEAR(steerAfterHolding(kLeft, frames), expected, 1e-15) << frames;
    EXPECT_NEAR(steerAfterHolding(kRight, frames), -expected, 1e-15) << frames;
  }
  const double tap = toDegrees(steerAfterHolding(kLeft, 12));
  EXPECT_GT(tap, 2.0);
  EXPECT_LT(tap, 3.5);
  // The former fixed rate gave 14.3 degrees for the same tap.
  EXPECT_LT(tap, toDegrees(p.steer_rate * 0.1) / 4.0);
}

TEST(SteeringRamp, FullLockAfterAboutSevenTenthsOfASecond) {
  const CarParams p;
  World world = rollingWorld(0.0);
  int frames = 0;
  while (world.car().steer < p.max_steer && frames < 600) {
    world.step(kLeft);
    ++frames;
  }
  EXPECT_GE(frames, 80);  // 0.67 s
  EXPECT_LE(frames, 88);  // 0.73 s
  // And back to the centre at the full rate once let go, as before the ramp.
  int back = 0;
  while (world.car().steer > 0.0 && back < 600) {
    world.step(kNone);
    ++back;
  }
  EXPECT_EQ(back, static_cast<int>(std::ceil(p.max_steer / (p.steer_rate / 120.0))));
}

TEST(SteeringRamp, ATapThenALetGoReturnsAndTheNextTapStartsSlowAgain) {
  World world = rollingWorld(0.0);
  holdKeys(world, kLeft, 12);
  const double first = world.car().steer;
  holdKeys(world, kNone, 30);
  EXPECT_EQ(world.car().steer, 0.0);
  EXPECT_EQ(world.controls().steer_steps, 0);
  holdKeys(world, kLeft, 12);
  EXPECT_EQ(world.car().steer, first);
}

TEST(SteeringRamp, CounterSteerReturnsAtTheFullRateThenRamps) {
  const CarParams p;
  World world = rollingWorld(0.0);
  holdKeys(world, kLeft, 120);
  ASSERT_EQ(world.car().steer, p.max_steer);
  world.step(kRight);
  EXPECT_DOUBLE_EQ(world.car().steer, p.max_steer - p.steer_rate / 120.0);
  EXPECT_EQ(world.controls().steer_steps, -1);
  // It stops at the centre, then goes on at the ramp's rate after the time already held.
  int frames = 1;
  while (world.car().steer > 0.0) {
    world.step(kRight);
    ++frames;
  }
  EXPECT_EQ(world.car().steer, 0.0);
  world.step(kRight);
  ++frames;
  EXPECT_NEAR(world.car().steer, -steerRampRate(p, frames / 120.0) / 120.0, 1e-15);
}

TEST(SteeringRamp, BothKeysCentreTheWheelAndRestartTheHold) {
  World world = rollingWorld(0.0);
  holdKeys(world, kLeft, 30);
  world.step(InputFrame{false, false, true, true});
  EXPECT_EQ(world.controls().steer_steps, 0);
  EXPECT_LT(world.car().steer, steerAfterHolding(kLeft, 30));
}

TEST(SteeringRamp, SteerAfterPredictsTheNextStep) {
  World world = rollingWorld(3.0);
  for (const InputFrame& in : {kLeft, kLeft, kNone, kRight, kDownLeft, kLeft, kLeft}) {
    const double predicted = world.steerAfter(in);
    world.step(in);
    EXPECT_EQ(world.car().steer, predicted);
  }
}

TEST(SteeringRamp, TheRampRateIsCappedAtTheSteerRate) {
  const CarParams p;
  EXPECT_EQ(steerRampRate(p, 0.0), p.steer_ramp_start);
  EXPECT_DOUBLE_EQ(steerRampRate(p, 1.0), p.steer_ramp_start + p.steer_ramp_accel);
  EXPECT_EQ(steerRampRate(p, 100.0), p.steer_rate);
  // A target nearer the centre on the same side is reached at the full rate.
  EXPECT_DOUBLE_EQ(steerStep(p, 0.5, 0.3, 0.0, 0.01), 0.5 - p.steer_rate * 0.01);
  // One beyond the centre stops there.
  EXPECT_EQ(steerStep(p, 0.01, -0.5, 0.0, 0.01), 0.0);
  EXPECT_EQ(steerStep(p, -0.01, 0.5, 0.0, 0.01), 0.0);
}

}  // namespace
}  // namespace cardemo
