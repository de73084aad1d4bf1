#include "play/picker_screen.hpp"

#include <algorithm>

#include "render/goal_overlay.hpp"

namespace cardemo {

std::vector<PickerRow> pickerRows(const std::vector<LevelEntry>& entries, const BestScores& best) {
  std::vector<PickerRow> rows;
  for (const LevelEntry& e : entries) {
    if (e.free_drive) {
      const ChainScore* chain = best.findChain(e.scene_name);
      rows.push_back({e.title,
                      chain == nullptr ? std::string("bay chain: no best yet")
                                       : "best " + chainScoreText(*chain),
                      e.task});
      continue;
    }
    const ParkingScore* score = best.find(e.scene_name);
    rows.push_back({std::to_string(e.order) + "   " + e.title,
                    score == nullptr ? std::string("not parked yet")
                                     : secondsText(score->seconds) + "  " + starsText(score->stars),
                    e.task});
  }
  return rows;
}

PickerScreen::PickerScreen(const std::vector<LevelEntry>& entries, const BestScores& best,
                           int selected)
    : rows_(pickerRows(entries, best)), progress_(progressText(levelProgress(entries, best))) {
  const int count = static_cast<int>(rows_.size());
  selected_ = count > 0 ? std::clamp(selected, 0, count - 1) : 0;
}

bool PickerScreen::act(PickerAction action) {
  const int count = static_cast<int>(rows_.size());
  switch (action) {
    case PickerAction::kUp:
      selected_ = moveSelection(selected_, -1, count);
      return false;
    case PickerAction::kDown:
      selected_ = moveSelection(selected_, 1, count);
      return false;
    case PickerAction::kChoose:
      if (count == 0) return false;  // nothing to play
      choice_ = selected_;
      return true;
    case PickerAction::kBack:
      choice_.reset();
      return true;
  }
  return false;
}

}  // namespace cardemo
