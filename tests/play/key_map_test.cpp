// The key table both platforms share: every key of docs/controls.md, in a level and in the picker.

#include "play/key_map.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace cardemo {
namespace {

using K = PlayActionKind;

std::vector<PlayAction> down(GameKey key, bool repeat = false) {
  std::vector<PlayAction> out;
  keyDownActions(key, repeat, out);
  return out;
}

std::vector<PlayAction> up(GameKey key) {
  std::vector<PlayAction> out;
  keyUpActions(key, out);
  return out;
}

std::vector<PlayAction> pad(PadButton button, bool pressed) {
  std::vector<PlayAction> out;
  padButtonActions(button, pressed, out);
  return out;
}

TEST(KeyMap, ArrowsAndWasdDriveAndRepeatPressesAgain) {
  const std::pair<GameKey, DriveKey> keys[] = {
      {GameKey::kUp, DriveKey::kUp},       {GameKey::kW, DriveKey::kUp},
      {GameKey::kDown, DriveKey::kDown},   {GameKey::kS, DriveKey::kDown},
      {GameKey::kLeft, DriveKey::kLeft},   {GameKey::kA, DriveKey::kLeft},
      {GameKey::kRight, DriveKey::kRight}, {GameKey::kD, DriveKey::kRight}};
  for (const auto& [key, drive] : keys) {
    const std::vector<PlayAction> pressed{{K::kDrivePress, drive}};
    EXPECT_EQ(down(key), pressed);
    EXPECT_EQ(down(key, true), pressed);
    EXPECT_EQ(up(key), (std::vector<PlayAction>{{K::kDriveRelease, drive}}));
    EXPECT_EQ(driveKeyOf(key), drive);
  }
}

TEST(KeyMap, SpaceIsTheHandbrakeAndConfirmsOncePerPress) {
  EXPECT_EQ(down(GameKey::kSpace),
            (std::vector<PlayAction>{{K::kDrivePress, DriveKey::kHandbrake}, {K::kConfirm}}));
  EXPECT_EQ(down(GameKey::kSpace, true),
            (std::vector<PlayAction>{{K::kDrivePress, DriveKey::kHandbrake}}));
  EXPECT_EQ(up(GameKey::kSpace),
            (std::vector<PlayAction>{{K::kDriveRelease, DriveKey::kHandbrake}}));
}

TEST(KeyMap, EveryOtherKeyActsOncePerPress) {
  const std::pair<GameKey, K> keys[] = {{GameKey::kEnter, K::kConfirm},
                                        {GameKey::kKeypadEnter, K::kConfirm},
                                        {GameKey::kEscape, K::kEscape},
                                        {GameKey::kP, K::kPause},
                                        {GameKey::kN, K::kNext},
                                        {GameKey::kR, K::kRestart},
                                        {GameKey::kB, K::kDebugOverlay},
                                        {GameKey::kM, K::kToggleMute},
                                        {GameKey::kF1, K::kHelp},
                                        {GameKey::kF11, K::kFullscreen},
                                        {GameKey::kF12, K::kScreenshot},
                                        {GameKey::kPlus, K::kZoomIn},
                                        {GameKey::kEquals, K::kZoomIn},
                                        {GameKey::kKeypadPlus, K::kZoomIn},
                                        {GameKey::kMinus, K::kZoomOut},
                                        {GameKey::kKeypadMinus, K::kZoomOut},
                                        {GameKey::kLeftBracket, K::kSlower},
                                        {GameKey::kRightBracket, K::kFaster}};
  for (const auto& [key, action] : keys) {
    EXPECT_EQ(down(key), std::vector<PlayAction>{{action}});
    EXPECT_TRUE(down(key, true).empty());
    EXPECT_TRUE(up(key).empty());
    EXPECT_FALSE(driveKeyOf(key).has_value());
  }
}

TEST(KeyMap, TheControllerButtons) {
  const std::pair<PadButton, DriveKey> dpad[] = {{PadButton::kDpadUp, DriveKey::kUp},
                                                 {PadButton::kDpadDown, DriveKey::kDown},
                                                 {PadButton::kDpadLeft, DriveKey::kLeft},
                                                 {PadButton::kDpadRight, DriveKey::kRight}};
  for (const auto& [button, drive] : dpad) {
    // No confirm from the D-pad: only the A button retries.
    EXPECT_EQ(pad(button, true), (std::vector<PlayAction>{{K::kDrivePress, drive}}));
    EXPECT_EQ(pad(button, false), (std::vector<PlayAction>{{K::kDriveRelease, drive}}));
  }
  EXPECT_EQ(pad(PadButton::kStart, true), std::vector<PlayAction>{{K::kPause}});
  EXPECT_EQ(pad(PadButton::kA, true), std::vector<PlayAction>{{K::kConfirm}});
  EXPECT_EQ(pad(PadButton::kBack, true), std::vector<PlayAction>{{K::kRestart}});
  for (PadButton b : {PadButton::kStart, PadButton::kA, PadButton::kBack}) {
    EXPECT_TRUE(pad(b, false).empty());
  }
}

TEST(KeyMap, ThePickerKeys) {
  EXPECT_EQ(pickerActionOf(GameKey::kUp, false), PickerAction::kUp);
  EXPECT_EQ(pickerActionOf(GameKey::kW, true), PickerAction::kUp);  // held: keeps moving
  EXPECT_EQ(pickerActionOf(GameKey::kDown, true), PickerAction::kDown);
  EXPECT_EQ(pickerActionOf(GameKey::kS, false), PickerAction::kDown);
  EXPECT_EQ(pickerActionOf(GameKey::kEnter, false), PickerAction::kChoose);
  EXPECT_EQ(pickerActionOf(GameKey::kKeypadEnter, false), PickerAction::kChoose);
  EXPECT_EQ(pickerActionOf(GameKey::kEnter, true), std::nullopt);
  EXPECT_EQ(pickerActionOf(GameKey::kEscape, false), PickerAction::kBack);
  EXPECT_EQ(pickerActionOf(GameKey::kEscape, true), std::nullopt);
  for (GameKey other : {GameKey::kSpace, GameKey::kLeft, GameKey::kA, GameKey::kN, GameKey::kF1}) {
    EXPECT_EQ(pickerActionOf(other, false), std::nullopt);
  }
}

}  // namespace
}  // namespace cardemo
