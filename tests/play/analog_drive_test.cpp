// AnalogDrive: the sigma-delta duty cycle, dead zones, the controller layout, merging.

#include "play/analog_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cardemo {
namespace {

TEST(SigmaDelta, ExtremesAreAlwaysOffOrAlwaysOn) {
  SigmaDelta zero, one, nan;
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(zero.next(0.0));
    EXPECT_TRUE(one.next(1.0));
    EXPECT_FALSE(nan.next(std::numeric_limits<double>::quiet_NaN()));
  }
  SigmaDelta over;
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(over.next(7.0));  // clamped to 1
}

TEST(SigmaDelta, HeldLevelGivesItsDutyCycleEvenlySpread) {
  SigmaDelta sd;
  int on = 0;
  for (int i = 0; i < 10; ++i) on += sd.next(0.3) ? 1 : 0;
  EXPECT_EQ(on, 3);
  SigmaDelta half;
  for (int i = 0; i < 20; ++i) EXPECT_EQ(half.next(0.5), i % 2 == 0) << i;
}

TEST(SigmaDelta, RunningCountStaysWithinHalfAStepOfTheLevelSum) {
  // Seeded random levels: the bound holds for every prefix.
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> level(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    SigmaDelta sd;
    double sum = 0.0;
    int on = 0;
    for (int i = 0; i < 2000; ++i) {
      const double x = level(rng);
      sum += x;
      on += sd.next(x) ? 1 : 0;
      ASSERT_LE(std::abs(on - sum), 0.5 + 1e-9) << trial << " " << i;
    }
  }
}

TEST(SigmaDelta, ResetRepeatsTheSameSequence) {
  SigmaDelta sd;
  std::vector<bool> first, second;
  for (int i = 0; i < 37; ++i) first.push_back(sd.next(0.37));
  sd.reset();
  for (int i = 0; i < 37; ++i) second.push_back(sd.next(0.37));
  EXPECT_EQ(first, second);
}

TEST(AxisLevel, DeadZoneAndFullTravel) {
  EXPECT_EQ(axisLevel(0), 0.0);
  EXPECT_EQ(axisLevel(4000), 0.0);  // inside the 15 % dead zone
  EXPECT_EQ(axisLevel(-4000), 0.0);
  EXPECT_EQ(axisLevel(32767), 1.0);
  EXPECT_EQ(axisLevel(-32768), -1.0);
  EXPECT_NEAR(axisLevel(static_cast<int>(32767 * 0.575)), 0.5, 1e-4);
  EXPECT_NEAR(axisLevel(-static_cast<int>(32767 * 0.575)), -0.5, 1e-4);
  // Monotonic over the whole range.
  double last = -2.0;
  for (int raw = -32768; raw <= 32767; raw += 97) {
    const double v = axisLevel(raw);
    EXPECT_GE(v, last);
    last = v;
  }
}

TEST(PadFromAxes, ControllerLayout) {
  const PadState rest = padFromAxes(0, 0, 0, 0, false);
  EXPECT_EQ(rest.steer, 0.0);
  EXPECT_EQ(rest.throttle, 0.0);
  EXPECT_EQ(rest.brake, 0.0);
  const PadState right_trigger = padFromAxes(-32768, 0, 0, 32767, true);
  EXPECT_EQ(right_trigger.steer, -1.0);
  EXPECT_EQ(right_trigger.throttle, 1.0);
  EXPECT_TRUE(right_trigger.handbrake);
  const PadState stick_up = padFromAxes(0, -32768, 0, 0, false);
  EXPECT_EQ(stick_up.throttle, 1.0);
  EXPECT_EQ(stick_up.brake, 0.0);
  const PadState stick_down = padFromAxes(0, 32767, 0, 0, false);
  EXPECT_EQ(stick_down.brake, 1.0);
  EXPECT_EQ(padFromAxes(0, 0, 32767, 0, false).brake, 1.0);
}

// A world in an empty scene, the car at `speed` m/s.
World worldAt(double speed) {
  Scene scene;
  scene.name = "pad";
  scene.player.speed = speed;
  return World(std::move(scene));
}

// The mean wheel angle over 2 s of holding `pad`, after 1.5 s to settle.
double meanSteer(const PadState& pad, World& world, AnalogDrive& drive) {
  for (int i = 0; i < 180; ++i) world.step(drive.sample(pad, world));
  double sum = 0.0;
  for (int i = 0; i < 240; ++i) {
    world.step(drive.sample(pad, world));
    sum += world.car().steer;
  }
  return sum / 240.0;
}

TEST(AnalogDrive, TheWheelFollowsTheStickInProportion) {
  // The keyboard ramp moves the wheel slowly on short presses, so pulses in proportion to the
  // stick would barely turn it; the servo holds the wheel at the stick's share of the lock.
  for (const double level : {-1.0, -0.75, -0.5, -0.25, -0.1, 0.1, 0.3, 0.6, 1.0}) {
    World world = worldAt(0.0);
    AnalogDrive drive;
    PadState pad;
    pad.steer = level;
    const double lock = effectiveLock(world.carParams(), 0.0, false);
    const double mean = meanSteer(pad, world, drive);
    // Within one step of the wheel's fastest rate (1.2 degrees) of the aim.
    EXPECT_NEAR(mean, -level * lock, world.carParams().steer_rate / 120.0) << level;
  }
}

TEST(AnalogDrive, ACentredStickLeavesTheKeyboardAlone) {
  World world = worldAt(0.0);
  AnalogDrive drive;
  const PadState centred;
  const InputFrame left{false, false, true, false};
  for (int i = 0; i < 60; ++i) {
    const InputFrame pad_keys = drive.sample(centred, world);
    EXPECT_FALSE(pad_keys.left || pad_keys.right) << i;
    world.step(mergeInputs(left, pad_keys));
  }
  EXPECT_GT(world.car().steer, 0.0);
}

TEST(AnalogDrive, AHalfTriggerHoldsHalfTheSteps) {
  World world = worldAt(0.0);
  AnalogDrive drive;
  PadState pad;
  pad.throttle = 0.5;
  int up = 0;
  for (int i = 0; i < 100; ++i) {
    const InputFrame f = drive.sample(pad, world);
    up += f.up ? 1 : 0;
    world.step(f);
  }
  EXPECT_EQ(up, 50);
  pad.handbrake = true;
  EXPECT_TRUE(drive.sample(pad, world).handbrake);
}

TEST(AnalogDrive, ABrakeSqueezeStopsAndHoldsUntilLetGoThenReverses) {
  World world = worldAt(5.0);
  AnalogDrive drive;
  PadState pad;
  pad.brake = 0.6;  // pulsed: each pulse is a press the simulation sees begin
  for (int i = 0; i < 600; ++i) world.step(drive.sample(pad, world));
  EXPECT_EQ(world.car().speed, 0.0);  // stopped and held, never reversing
  pad.brake = 0.0;
  world.step(drive.sample(pad, world));
  pad.brake = 0.6;
  for (int i = 0; i < 120; ++i) world.step(drive.sample(pad, world));
  EXPECT_LT(world.car().speed, -0.5);
  // Out of reverse, the throttle likewise.
  pad.brake = 0.0;
  pad.throttle = 0.6;
  for (int i = 0; i < 600; ++i) world.step(drive.sample(pad, world));
  EXPECT_EQ(world.car().speed, 0.0);
}

TEST(AnalogDrive, SameAnalogSequenceSameKeys) {
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> axis(-32768, 32767);
  std::vector<PadState> pads;
  for (int i = 0; i < 500; ++i) {
    const int left_x = axis(rng);
    const int left_y = axis(rng);
    const int trigger_left = std::abs(axis(rng));
    const int trigger_right = std::abs(axis(rng));
    pads.push_back(padFromAxes(left_x, left_y, trigger_left, trigger_right, false));
  }
  AnalogDrive a, b;
  World wa = worldAt(3.0), wb = worldAt(3.0);
  for (const PadState& p : pads) {
    const InputFrame fa = a.sample(p, wa);
    EXPECT_EQ(fa, b.sample(p, wb));
    wa.step(fa);
    wb.step(fa);
  }
}

TEST(MergeInputs, EitherSourceHoldsTheKey) {
  const InputFrame keyboard{true, false, false, false};
  const InputFrame pad{false, false, true, false};
  const InputFrame both = mergeInputs(keyboard, pad);
  EXPECT_TRUE(both.up);
  EXPECT_TRUE(both.left);
  EXPECT_FALSE(both.down);
  EXPECT_FALSE(both.right);
}

}  // namespace
}  // namespace cardemo
