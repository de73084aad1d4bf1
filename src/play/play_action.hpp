#pragma once
/// What the player asked for in one drawn frame, as plain data: the platforms turn their key and
/// button events into these (play/key_map), and PlayScreen gives them their meaning.

#include <cstdint>

#include "play/input_latch.hpp"

namespace cardemo {

/// One request of the player (or of the window) in a level.
enum class PlayActionKind : std::uint8_t {
  kDrivePress,    ///< A driving key went down (PlayAction::key says which).
  kDriveRelease,  ///< A driving key went up.
  kReleaseAll,    ///< Every driving key is up (the window lost the keyboard focus).
  kPause,         ///< P, the controller's Start: pause or resume.
  kHelp,          ///< F1: show or hide the help.
  kRestart,       ///< R, the controller's Back: restart the scene now.
  kConfirm,       ///< Enter, Space, the controller's A: retry once the run has ended.
  kEscape,        ///< Esc: back to the picker, or quit.
  kNext,          ///< N: one step while paused; the next level once parked.
  kZoomIn,        ///< +: closer.
  kZoomOut,       ///< -: farther.
  kSlower,        ///< [: halves the replay speed.
  kFaster,        ///< ]: doubles the replay speed.
  kDebugOverlay,  ///< B: the debug overlay on or off.
  kToggleMute,    ///< M: sound off or on.
  kScreenshot,    ///< F12: save the frame about to be drawn.
  kFullscreen,    ///< F11: full screen on or off.
  kQuit,          ///< The window was closed: end the program.
};

/// One action; `key` matters only for kDrivePress and kDriveRelease.
struct PlayAction {
  PlayActionKind kind = PlayActionKind::kPause;  ///< What was asked.
  DriveKey key = DriveKey::kUp;                  ///< The driving key pressed or released.

  /// Member-wise equality.
  [[nodiscard]] bool operator==(const PlayAction&) const = default;
};

}  // namespace cardemo
