#pragma once
/// The scene picker of `cardemo play` without SCENE, and the levels it opens, in one window. This
/// header is SDL-free.

#include <optional>
#include <vector>

#include "platform/game_window.hpp"
#include "play/best_scores.hpp"
#include "play/level_list.hpp"

namespace cardemo {

class SdlWindow;

/// Shows the picker in `window`: `entries` with their `best` scores, row `selected` highlighted.
/// Returns the row chosen with Enter, or nullopt on Esc, window close or a stop signal.
[[nodiscard]] std::optional<int> runScenePicker(SdlWindow& window,
                                                const std::vector<LevelEntry>& entries,
                                                const BestScores& best, int selected);

/// The picker, then the level chosen, then the picker again (Esc in a level) or the next level (N
/// once parked), all in one window, until Esc in the picker, window close or a stop signal
/// (play/picker_flow decides which comes next). `base` is each game's options but the scene; the
/// best scores are read from `base.play.best_scores_path` each time the picker opens. Returns the
/// exit status as runGameWindow() does.
[[nodiscard]] int runPickerAndLevels(const std::vector<LevelEntry>& entries,
                                     const GameWindowOptions& base);

}  // namespace cardemo
