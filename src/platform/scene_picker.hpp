#pragma once
/// The scene picker window of `cardemo play` without SCENE. This header is SDL-free.

#include <optional>
#include <string>
#include <vector>

#include "play/best_scores.hpp"
#include "play/level_list.hpp"

namespace cardemo {

/// Opens a window listing `entries` (with their best scores) and returns the path chosen with
/// Enter (SDL is left initialised for the game window), or nullopt on Esc or window close. `status`
/// is 1 when no window could be opened (the message is on stderr), else 0.
[[nodiscard]] std::optional<std::string> runScenePicker(const std::vector<LevelEntry>& entries,
                                                        const BestScores& best, int& status);

}  // namespace cardemo
