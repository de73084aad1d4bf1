// FixedStepClock: whole steps out of real time, the catch-up clamp, alpha and the speed factor.

#include "play/fixed_step_clock.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

TEST(FixedStepClock, AccumulatesUntilAWholeStep) {
  FixedStepClock clock(0.01, 8);
  EXPECT_EQ(clock.advance(0.004), 0);
  EXPECT_NEAR(clock.alpha(), 0.4, 1e-9);
  EXPECT_EQ(clock.advance(0.004), 0);
  EXPECT_EQ(clock.advance(0.004), 1);
  EXPECT_NEAR(clock.alpha(), 0.2, 1e-9);
  EXPECT_EQ(clock.advance(0.025), 2);
  EXPECT_NEAR(clock.alpha(), 0.7, 1e-9);
}

TEST(FixedStepClock, ClampsCatchUpAndDropsTheRest) {
  FixedStepClock clock(0.01, 8);
  EXPECT_EQ(clock.advance(1.0), 8);  // a one-second hitch runs 8 steps, not 100
  EXPECT_NEAR(clock.droppedSeconds(), 0.92, 1e-9);
  EXPECT_GE(clock.alpha(), 0.0);
  EXPECT_LT(clock.alpha(), 1.0);
  EXPECT_EQ(clock.advance(0.0), 0);  // nothing left over to spiral on
}

TEST(FixedStepClock, SpeedScalesTime) {
  FixedStepClock fast(0.01, 8);
  EXPECT_EQ(fast.advance(0.01, 4.0), 4);
  FixedStepClock slow(0.01, 8);
  EXPECT_EQ(slow.advance(0.01, 0.25), 0);
  EXPECT_NEAR(slow.alpha(), 0.25, 1e-9);
  EXPECT_EQ(slow.advance(0.03, 0.25), 1);
}

TEST(FixedStepClock, NegativeTimeIsIgnored) {
  FixedStepClock clock(0.01, 8);
  EXPECT_EQ(clock.advance(-5.0), 0);
  EXPECT_EQ(clock.alpha(), 0.0);
}

TEST(FixedStepClock, AlphaStaysInRangeOverManyFrames) {
  FixedStepClock clock(1.0 / 120.0, 8);
  int steps = 0;
  double total = 0.0;
  for (int i = 0; i < 6000; ++i) {
    const double dt = 1.0 / 60.0 + (i % 7) * 1e-4;
    total += dt;
    steps += clock.advance(dt);
    ASSERT_GE(clock.alpha(), 0.0);
    ASSERT_LT(clock.alpha(), 1.0);
  }
  EXPECT_NEAR(steps, total * 120.0, 1.0);  // no time lost when frames are fast enough
}

}  // namespace
}  // namespace cardemo
