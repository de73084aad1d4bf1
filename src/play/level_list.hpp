#pragma once
/// The scenes the picker of `cardemo play` offers: the bundled levels in order, then free drive.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "play/best_scores.hpp"

namespace cardemo {

/// One scene the picker lists.
struct LevelEntry {
  std::string path;         ///< Scene file.
  std::string title;        ///< Shown in the picker.
  std::string scene_name;   ///< The scene's `name` (the key of its best score).
  int order = 0;            ///< `level.order`; 0 for free drive.
  bool free_drive = false;  ///< The free-drive lot (no goal).
  std::string task;         ///< `level.task`, shown under the title when selected (may be empty).
};

/// The scenes with a `level` object in `ASSETS/scenes/levels/*.json`, sorted by order, then title,
/// then file name, followed by the free-drive lot `ASSETS/scenes/parking-lot.json` when it exists.
/// A level file that does not load is left out with a one-line warning in `warnings`.
[[nodiscard]] std::vector<LevelEntry> listLevels(const std::string& assets_folder,
                                                 std::vector<std::string>& warnings);

/// The level after entry `current` (the next entry that is not free drive), or nullopt when
/// `current` is the last level or free drive.
[[nodiscard]] std::optional<std::size_t> nextLevel(const std::vector<LevelEntry>& entries,
                                                   std::size_t current);

/// The player's progress over the levels of a picker list (free drive does not count).
struct LevelProgress {
  int levels = 0;  ///< Levels listed.
  int parked = 0;  ///< Levels with a best score.
  int stars = 0;   ///< Their best scores' stars, summed.
  /// The most stars there are: kMaxStars a level.
  [[nodiscard]] int possibleStars() const { return kMaxStars * levels; }
};

/// Progress over `entries` from the best scores (keyed by each entry's scene name).
[[nodiscard]] LevelProgress levelProgress(const std::vector<LevelEntry>& entries,
                                          const BestScores& best);

/// The picker's progress line, e.g. "4 / 6 levels parked     \u2605 9 / 18" (empty without
/// levels).
[[nodiscard]] std::string progressText(const LevelProgress& progress);

/// `selected` moved by `delta` rows in a list of `count`, wrapping at both ends (0 when empty).
[[nodiscard]] int moveSelection(int selected, int delta, int count);

}  // namespace cardemo
