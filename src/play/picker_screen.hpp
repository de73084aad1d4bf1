#pragma once
/// The scene picker's rules, with no window: its rows, the selection, and what ends it. The
/// platforms turn keys into PickerActions (play/key_map) and draw what it says
/// (render/scene_picker_view).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "play/best_scores.hpp"
#include "play/level_list.hpp"
#include "render/scene_picker_view.hpp"

namespace cardemo {

/// What the player does in the picker.
enum class PickerAction : std::uint8_t {
  kUp,      ///< Up or W: the row above (wraps).
  kDown,    ///< Down or S: the row below (wraps).
  kChoose,  ///< Enter: play the selected row.
  kBack,    ///< Esc: leave the picker.
};

/// The picker rows of `entries`: order and title, then the best time and stars or "not parked
/// yet" (free drive: its best bay chain, "best 4 bays in 170.2 s", or "bay chain: no best yet"),
/// and the task.
[[nodiscard]] std::vector<PickerRow> pickerRows(const std::vector<LevelEntry>& entries,
                                                const BestScores& best);

/// One showing of the picker.
class PickerScreen {
 public:
  /// The picker over `entries` with their `best` scores, row `selected` highlighted (clamped to
  /// the rows).
  PickerScreen(const std::vector<LevelEntry>& entries, const BestScores& best, int selected);

  /// Applies `action`; returns true when it ends the picker (then choice() says how).
  bool act(PickerAction action);
  /// The row chosen with Enter, or nullopt when the player left with Esc (or not yet chosen).
  [[nodiscard]] std::optional<int> choice() const { return choice_; }

  /// The rows to draw.
  [[nodiscard]] const std::vector<PickerRow>& rows() const { return rows_; }
  /// The highlighted row.
  [[nodiscard]] int selected() const { return selected_; }
  /// The progress line under the title (empty without levels).
  [[nodiscard]] const std::string& progress() const { return progress_; }

 private:
  std::vector<PickerRow> rows_;
  std::string progress_;
  int selected_ = 0;
  std::optional<int> choice_;
};

}  // namespace cardemo
