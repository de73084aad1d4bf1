// PickerScreen: the rows, the selection that wraps, and what Enter and Esc do.

#include "play/picker_screen.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

std::vector<LevelEntry> threeEntries() {
  return {{"l1.json", "Straight in", "level-1", 1, false, "Park ahead"},
          {"l2.json", "Reverse", "level-2", 2, false, ""},
          {"lot.json", "Free drive", "parking-lot", 0, true, "Drive anywhere"}};
}

TEST(PickerScreen, RowsShowOrderTitleBestAndTask) {
  BestScores best;
  ParkingScore score;
  score.seconds = 12.34;
  score.stars = 2;
  (void)best.offer("level-2", score);
  const std::vector<PickerRow> rows = pickerRows(threeEntries(), best);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].title, "1   Straight in");
  EXPECT_EQ(rows[0].detail, "not parked yet");
  EXPECT_EQ(rows[0].task, "Park ahead");
  EXPECT_EQ(rows[1].detail, "12.3 s  \xE2\x98\x85\xE2\x98\x85\xE2\x98\x86");
  EXPECT_EQ(rows[2].title, "Free drive");
  EXPECT_EQ(rows[2].detail, "bay chain: no best yet");
  (void)best.offerChain("parking-lot", {4, 20424, 170.2});
  EXPECT_EQ(pickerRows(threeEntries(), best)[2].detail, "best 4 bays in 170.2 s");
  EXPECT_EQ(pickerRows(threeEntries(), best)[1].detail, rows[1].detail) << "a chain is no level";
  const PickerScreen picker(threeEntries(), best, 0);
  EXPECT_EQ(picker.progress(), progressText(levelProgress(threeEntries(), best)));
  EXPECT_EQ(picker.rows().size(), 3u);
}

TEST(PickerScreen, SelectionWrapsAndStartsClamped) {
  PickerScreen picker(threeEntries(), {}, 7);
  EXPECT_EQ(picker.selected(), 2);
  EXPECT_FALSE(picker.act(PickerAction::kDown));
  EXPECT_EQ(picker.selected(), 0);
  EXPECT_FALSE(picker.act(PickerAction::kUp));
  EXPECT_EQ(picker.selected(), 2);
  EXPECT_EQ(PickerScreen(threeEntries(), {}, -3).selected(), 0);
}

TEST(PickerScreen, EnterChoosesAndEscLeaves) {
  PickerScreen picker(threeEntries(), {}, 1);
  EXPECT_TRUE(picker.act(PickerAction::kChoose));
  EXPECT_EQ(picker.choice(), 1);
  PickerScreen left(threeEntries(), {}, 1);
  EXPECT_TRUE(left.act(PickerAction::kBack));
  EXPECT_EQ(left.choice(), std::nullopt);
}

TEST(PickerScreen, AnEmptyListCannotBeChosenFrom) {
  PickerScreen empty({}, {}, 0);
  EXPECT_FALSE(empty.act(PickerAction::kDown));
  EXPECT_EQ(empty.selected(), 0);
  EXPECT_FALSE(empty.act(PickerAction::kChoose));
  EXPECT_TRUE(empty.progress().empty());
  EXPECT_TRUE(empty.act(PickerAction::kBack));
}

}  // namespace
}  // namespace cardemo
