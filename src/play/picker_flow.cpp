#include "play/picker_flow.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "io/scene_json.hpp"

namespace cardemo {

PickerFlow::PickerFlow(std::vector<LevelEntry> entries, int first_attempt)
    : entries_(std::move(entries)), next_attempt_(std::max(1, first_attempt)) {}

void PickerFlow::picked(std::optional<int> row) {
  const int count = static_cast<int>(entries_.size());
  if (!row || *row < 0 || *row >= count) {
    done_ = true;
    return;
  }
  play_ = *row;
  selected_ = *row;
}

Parsed<PlayScreenConfig> PickerFlow::levelConfig(const PlayScreenConfig& base) const {
  const auto index = static_cast<std::size_t>(std::max(play_, 0));
  const LevelEntry& entry = entries_.at(index);
  Parsed<Scene> scene = loadScene(entry.path);
  if (!scene.ok()) return scene.error();
  PlayScreenConfig config = base;
  config.session.scene = std::move(scene).value();
  config.session.scene_path = entry.path;
  config.session.first_attempt = next_attempt_;
  config.links = {true, nextLevel(entries_, index).has_value()};
  return config;
}

void PickerFlow::levelEnded(const GameOutcome& outcome) {
  next_attempt_ = outcome.last_attempt + 1;
  if (outcome.exit == LevelExit::kNextLevel) {
    const auto index = static_cast<std::size_t>(std::max(play_, 0));
    play_ = static_cast<int>(nextLevel(entries_, index).value_or(0));
    selected_ = play_;
  } else if (outcome.exit == LevelExit::kPicker) {
    play_ = -1;
  } else {
    done_ = true;
  }
}

}  // namespace cardemo
