#pragma once
/// Which key does what (docs/controls.md), for every platform: the SDL window and the web page
/// name their keys and controller buttons with GameKey and PadButton, and this table turns them
/// into the actions of a level (PlayAction) or of the picker (PickerAction).

#include <cstdint>
#include <optional>
#include <vector>

#include "play/picker_screen.hpp"
#include "play/play_action.hpp"

namespace cardemo {

/// The keys the game reads, by name. W, A, S and D name positions (the keys where QWERTY has
/// them), so that the same four keys drive on any layout; the others name the key's symbol.
enum class GameKey : std::uint8_t {
  kUp,            ///< Arrow up.
  kDown,          ///< Arrow down.
  kLeft,          ///< Arrow left.
  kRight,         ///< Arrow right.
  kW,             ///< The key in QWERTY's W position.
  kA,             ///< The key in QWERTY's A position.
  kS,             ///< The key in QWERTY's S position.
  kD,             ///< The key in QWERTY's D position.
  kSpace,         ///< Space bar.
  kEnter,         ///< Return.
  kKeypadEnter,   ///< The keypad's Enter.
  kEscape,        ///< Esc.
  kP,             ///< P.
  kN,             ///< N.
  kR,             ///< R.
  kB,             ///< B.
  kM,             ///< M.
  kF1,            ///< F1.
  kF11,           ///< F11.
  kF12,           ///< F12.
  kPlus,          ///< +.
  kEquals,        ///< = (+ without Shift on most layouts).
  kKeypadPlus,    ///< The keypad's +.
  kMinus,         ///< -.
  kKeypadMinus,   ///< The keypad's -.
  kLeftBracket,   ///< [.
  kRightBracket,  ///< ].
};

/// The game controller's buttons the game reads (its sticks and triggers are a PadState).
enum class PadButton : std::uint8_t {
  kDpadUp,     ///< D-pad up.
  kDpadDown,   ///< D-pad down.
  kDpadLeft,   ///< D-pad left.
  kDpadRight,  ///< D-pad right.
  kStart,      ///< Start.
  kA,          ///< The bottom face button.
  kBack,       ///< Back (Select).
};

/// The driving key of `key` (arrows, WASD, Space), if it is one.
[[nodiscard]] std::optional<DriveKey> driveKeyOf(GameKey key);

/// Appends to `out` what pressing `key` does in a level. `repeat` marks the keyboard's
/// auto-repeat of a held key: a driving key is pressed again, every other key acts once per press.
/// Space is the handbrake and also confirms (retry once the run has ended).
void keyDownActions(GameKey key, bool repeat, std::vector<PlayAction>& out);

/// Appends to `out` what releasing `key` does in a level (only driving keys do something).
void keyUpActions(GameKey key, std::vector<PlayAction>& out);

/// Appends to `out` what pressing (`down`) or releasing a controller button does in a level: the
/// D-pad drives like the arrows, Start pauses, A confirms, Back restarts.
void padButtonActions(PadButton button, bool down, std::vector<PlayAction>& out);

/// What pressing `key` does in the picker (`repeat`: auto-repeat, which moves but never chooses
/// or leaves), if anything.
[[nodiscard]] std::optional<PickerAction> pickerActionOf(GameKey key, bool repeat);

}  // namespace cardemo
