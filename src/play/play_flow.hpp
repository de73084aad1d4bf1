#pragma once
/// The game's flow between the keys and the simulation: pause, help, the "your turn" hand-over
/// after a replay, playback speed, and what Enter/Space, N and Esc mean. No window, no clock.

#include <cstdint>
#include <string>

namespace cardemo {

/// Where the player asked to go from a level.
enum class LevelExit : std::uint8_t {
  kStay,       ///< Nothing: keep playing this level.
  kQuit,       ///< End the program.
  kPicker,     ///< Back to the scene picker.
  kNextLevel,  ///< On to the picker's next level.
};

/// What surrounds the level being played (set by whoever started it).
struct LevelLinks {
  bool from_picker = false;  ///< Started from the scene picker: Esc returns to it.
  bool has_next = false;     ///< The picker has a level after this one: N opens it once parked.
};

/// Esc: back to the picker when the level came from it, else quit.
[[nodiscard]] LevelExit escapeExit(const LevelLinks& links);

/// The keys line of an end panel (PARKED when `parked`, else TIME UP or GAME OVER): retry, next
/// level only when parked with a next level, and Esc's meaning.
[[nodiscard]] std::string endPanelKeys(const LevelLinks& links, bool parked);

/// Decides whether the simulation runs this frame, and what the flow keys do. The window feeds it
/// key presses and the session's state; the session never sees it.
class PlayFlow {
 public:
  /// Slowest and fastest playback speed.
  static constexpr double kMinSpeed = 0.25, kMaxSpeed = 8.0;

  /// P (or the controller's Start): pause or resume.
  void togglePause() { paused_ = !paused_; }
  /// F1: show or hide the help; the simulation holds while it is shown.
  void toggleHelp() { help_ = !help_; }
  /// N: one step, only while paused by P (not behind the help or the "your turn" banner).
  void stepOnce() { step_once_ = paused_ && !help_ && !your_turn_; }
  /// N with the level's state: once it is parked, the next level (kStay when there is none);
  /// before that, stepOnce().
  [[nodiscard]] LevelExit next(bool parked, const LevelLinks& links);
  /// ]: doubles the playback speed (up to kMaxSpeed).
  void faster();
  /// [: halves the playback speed (down to kMinSpeed).
  void slower();

  /// Called every frame with whether the replay is still playing: when a replay has just run out
  /// (and the game has not ended), the flow stops at "your turn" and the speed returns to 1x.
  void update(bool playing_back, bool ended);
  /// A driving key went down: it ends the "your turn" wait (live input takes over from here).
  void driveKeyPressed() { your_turn_ = false; }
  /// Enter, or Space when not driving: true when it should restart the game (it has ended),
  /// false when it does nothing here. Also ends the "your turn" wait.
  [[nodiscard]] bool confirm(bool ended);
  /// The game was restarted: pause, help and speed are kept; the hand-over starts afresh.
  void restarted();

  /// Number of fixed steps to run now, given those the clock asks for: 0 while paused, while the
  /// help is shown or while waiting at "your turn"; 1 for a single step while paused (N).
  [[nodiscard]] int stepsToRun(int clock_steps);
  /// True when the clock should not accumulate time (nothing runs).
  [[nodiscard]] bool holding() const { return paused_ || help_ || your_turn_; }

  /// True while paused with P.
  [[nodiscard]] bool paused() const { return paused_; }
  /// True while the help is shown.
  [[nodiscard]] bool help() const { return help_; }
  /// True while waiting for the player after a replay ran out.
  [[nodiscard]] bool yourTurn() const { return your_turn_; }
  /// Playback speed: the chosen one while a replay plays, else 1.
  [[nodiscard]] double speed() const { return playing_back_ ? speed_ : 1.0; }
  /// The chosen playback speed (shown while a replay plays).
  [[nodiscard]] double chosenSpeed() const { return speed_; }

 private:
  bool paused_ = false;
  bool help_ = false;
  bool step_once_ = false;
  bool your_turn_ = false;
  bool playing_back_ = false;
  bool was_playing_back_ = false;
  double speed_ = 1.0;
};

}  // namespace cardemo
