#include "play/key_map.hpp"

namespace cardemo {
namespace {

// The keys that act once per press, and what they ask for.
std::optional<PlayActionKind> pressAction(GameKey key) {
  switch (key) {
    case GameKey::kEscape:
      return PlayActionKind::kEscape;
    case GameKey::kEnter:
    case GameKey::kKeypadEnter:
      return PlayActionKind::kConfirm;
    case GameKey::kP:
      return PlayActionKind::kPause;
    case GameKey::kN:
      return PlayActionKind::kNext;
    case GameKey::kR:
      return PlayActionKind::kRestart;
    case GameKey::kB:
      return PlayActionKind::kDebugOverlay;
    case GameKey::kM:
      return PlayActionKind::kToggleMute;
    case GameKey::kF1:
      return PlayActionKind::kHelp;
    case GameKey::kF11:
      return PlayActionKind::kFullscreen;
    case GameKey::kF12:
      return PlayActionKind::kScreenshot;
    case GameKey::kPlus:
    case GameKey::kEquals:
    case GameKey::kKeypadPlus:
      return PlayActionKind::kZoomIn;
    case GameKey::kMinus:
    case GameKey::kKeypadMinus:
      return PlayActionKind::kZoomOut;
    case GameKey::kLeftBracket:
      return PlayActionKind::kSlower;
    case GameKey::kRightBracket:
      return PlayActionKind::kFaster;
    default:
      return std::nullopt;
  }
}

}  // namespace

std::optional<DriveKey> driveKeyOf(GameKey key) {
  switch (key) {
    case GameKey::kUp:
    case GameKey::kW:
      return DriveKey::kUp;
    case GameKey::kDown:
    case GameKey::kS:
      return DriveKey::kDown;
    case GameKey::kLeft:
    case GameKey::kA:
      return DriveKey::kLeft;
    case GameKey::kRight:
    case GameKey::kD:
      return DriveKey::kRight;
    case GameKey::kSpace:
      return DriveKey::kHandbrake;
    default:
      return std::nullopt;
  }
}

void keyDownActions(GameKey key, bool repeat, std::vector<PlayAction>& out) {
  if (const std::optional<DriveKey> drive = driveKeyOf(key)) {
    out.push_back({PlayActionKind::kDrivePress, *drive});
    if (*drive == DriveKey::kHandbrake && !repeat) out.push_back({PlayActionKind::kConfirm});
    return;
  }
  if (repeat) return;
  if (const std::optional<PlayActionKind> action = pressAction(key)) out.push_back({*action});
}

void keyUpActions(GameKey key, std::vector<PlayAction>& out) {
  if (const std::optional<DriveKey> drive = driveKeyOf(key)) {
    out.push_back({PlayActionKind::kDriveRelease, *drive});
  }
}

void padButtonActions(PadButton button, bool down, std::vector<PlayAction>& out) {
  const auto drive = [&](DriveKey key) {
    out.push_back({down ? PlayActionKind::kDrivePress : PlayActionKind::kDriveRelease, key});
  };
  switch (button) {
    case PadButton::kDpadUp:
      return drive(DriveKey::kUp);
    case PadButton::kDpadDown:
      return drive(DriveKey::kDown);
    case PadButton::kDpadLeft:
      return drive(DriveKey::kLeft);
    case PadButton::kDpadRight:
      return drive(DriveKey::kRight);
    case PadButton::kStart:
      if (down) out.push_back({PlayActionKind::kPause});
      return;
    case PadButton::kA:
      if (down) out.push_back({PlayActionKind::kConfirm});
      return;
    case PadButton::kBack:
      if (down) out.push_back({PlayActionKind::kRestart});
      return;
  }
}

std::optional<PickerAction> pickerActionOf(GameKey key, bool repeat) {
  switch (key) {
    case GameKey::kUp:
    case GameKey::kW:
      return PickerAction::kUp;
    case GameKey::kDown:
    case GameKey::kS:
      return PickerAction::kDown;
    case GameKey::kEnter:
    case GameKey::kKeypadEnter:
      if (repeat) return std::nullopt;
      return PickerAction::kChoose;
    case GameKey::kEscape:
      if (repeat) return std::nullopt;
      return PickerAction::kBack;
    default:
      return std::nullopt;
  }
}

}  // namespace cardemo
