#pragma once
/// The scene picker and the levels it opens, in turn: which comes next (the picker, a level, the
/// next level, the end) and what each level starts with. No window: the platforms show the
/// picker (PickerScreen) and play the levels (PlayScreen).

#include <optional>
#include <vector>

#include "io/input_error.hpp"
#include "play/level_list.hpp"
#include "play/play_screen.hpp"

namespace cardemo {

/// Starts at the picker. Esc in a level returns to it with that level selected; N once parked
/// opens the next level; attempts are numbered across levels, so that `--record` keeps each one.
class PickerFlow {
 public:
  /// Over `entries` (listLevels()); the first level's first attempt is `first_attempt`.
  PickerFlow(std::vector<LevelEntry> entries, int first_attempt);

  /// True once the player left the picker, or a level was left other than for the picker or the
  /// next level (quit, window closed).
  [[nodiscard]] bool done() const { return done_; }
  /// True when the picker shows next (at the start, and after Esc in a level).
  [[nodiscard]] bool picking() const { return !done_ && play_ < 0; }
  /// The row the picker highlights: the level played last (the first row at the start).
  [[nodiscard]] int selected() const { return selected_; }
  /// The picker's answer: the row chosen, or nullopt when the player left it (then done()).
  void picked(std::optional<int> row);
  /// The level to play now (when neither picking() nor done()): `base` with the entry's scene
  /// loaded, its links (from the picker, whether a next level follows) and the attempt count
  /// continued; or the error of a scene that does not load.
  [[nodiscard]] Parsed<PlayScreenConfig> levelConfig(const PlayScreenConfig& base) const;
  /// The level played ended with `outcome`: kNextLevel opens the next level, kPicker the picker,
  /// anything else ends the flow.
  void levelEnded(const GameOutcome& outcome);

  /// The scenes listed.
  [[nodiscard]] const std::vector<LevelEntry>& entries() const { return entries_; }

 private:
  std::vector<LevelEntry> entries_;
  int selected_ = 0;
  int next_attempt_ = 1;
  int play_ = -1;  // the entry to play next, or -1: the picker
  bool done_ = false;
};

}  // namespace cardemo
