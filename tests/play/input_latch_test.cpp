// InputLatch: held keys, and presses shorter than one step still count for that step.

#include "play/input_latch.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

TEST(InputLatch, HeldKeysStayHeldAcrossSamples) {
  InputLatch latch;
  latch.press(DriveKey::kUp);
  latch.press(DriveKey::kLeft);
  EXPECT_EQ(latch.sample(), (InputFrame{true, false, true, false}));
  EXPECT_EQ(latch.sample(), (InputFrame{true, false, true, false}));
  latch.release(DriveKey::kLeft);
  EXPECT_EQ(latch.sample(), (InputFrame{true, false, false, false}));
}

TEST(InputLatch, ShortPressBetweenSamplesCountsOnce) {
  InputLatch latch;
  EXPECT_EQ(latch.sample(), InputFrame{});
  latch.press(DriveKey::kRight);
  latch.release(DriveKey::kRight);  // tapped and released before the step ran
  EXPECT_EQ(latch.sample(), (InputFrame{false, false, false, true}));
  EXPECT_EQ(latch.sample(), InputFrame{});
}

TEST(InputLatch, AReleaseAndPressBetweenStepsIsSeenAsAFreshPress) {
  InputLatch latch;
  latch.press(DriveKey::kDown);
  EXPECT_EQ(latch.sample(), (InputFrame{false, true, false, false}));
  latch.release(DriveKey::kDown);
  latch.press(DriveKey::kDown);  // within one step: the step runs with Down up, the next with it
  EXPECT_EQ(latch.sample(), InputFrame{});
  EXPECT_EQ(latch.sample(), (InputFrame{false, true, false, false}));
  EXPECT_EQ(latch.sample(), (InputFrame{false, true, false, false}));
  // Released, pressed and released again between two steps: up for one step, then the tap's step.
  latch.release(DriveKey::kDown);
  latch.press(DriveKey::kDown);
  latch.release(DriveKey::kDown);
  EXPECT_EQ(latch.sample(), InputFrame{});
  EXPECT_EQ(latch.sample(), (InputFrame{false, true, false, false}));
  EXPECT_EQ(latch.sample(), InputFrame{});
}

TEST(InputLatch, EveryKeyMapsToItsField) {
  const std::pair<DriveKey, InputFrame> cases[] = {
      {DriveKey::kUp, {true, false, false, false}},
      {DriveKey::kDown, {false, true, false, false}},
      {DriveKey::kLeft, {false, false, true, false}},
      {DriveKey::kRight, {false, false, false, true}},
      {DriveKey::kHandbrake, {false, false, false, false, true}},
  };
  for (const auto& [key, expected] : cases) {
    InputLatch latch;
    latch.press(key);
    EXPECT_EQ(latch.sample(), expected);
  }
}

TEST(InputLatch, ReleaseAllForgetsEverything) {
  InputLatch latch;
  latch.press(DriveKey::kUp);
  latch.press(DriveKey::kDown);
  latch.releaseAll();
  EXPECT_EQ(latch.sample(), InputFrame{});
}

}  // namespace
}  // namespace cardemo
