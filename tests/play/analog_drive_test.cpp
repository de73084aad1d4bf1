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

TEST(AnalogDrive, HalfStickSteersHalfTheSteps) {
  AnalogDrive drive;
  PadState pad;
  pad.steer = -0.5;
  pad.throttle = 1.0;
  int left = 0, right = 0, up = 0;
  for (int i = 0; i < 100; ++i) {
    const InputFrame f = drive.sample(pad);
    left += f.left ? 1 : 0;
    right += f.right ? 1 : 0;
    up += f.up ? 1 : 0;
  }
  EXPECT_EQ(left, 50);
  pad.handbrake = true;
  EXPECT_TRUE(drive.sample(pad).handbrake);
  EXPECT_EQ(right, 0);
  EXPECT_EQ(up, 100);
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
  for (const PadState& p : pads) EXPECT_EQ(a.sample(p), b.sample(p));
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
