// PickerFlow: the picker, the level chosen, Esc back to the picker, N on to the next level, and
// attempts numbered across levels.

#include "play/picker_flow.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

std::vector<LevelEntry> bundledEntries() {
  std::vector<std::string> warnings;
  std::vector<LevelEntry> entries =
      listLevels(std::string(CARDEMO_SOURCE_DIR) + "/assets", warnings);
  EXPECT_TRUE(warnings.empty());
  return entries;
}

GameOutcome ended(LevelExit exit, int last_attempt) {
  return {0, exit, last_attempt};
}

TEST(PickerFlow, StartsAtThePickerAndEndsWhenItIsLeft) {
  PickerFlow flow(bundledEntries(), 1);
  EXPECT_TRUE(flow.picking());
  EXPECT_FALSE(flow.done());
  EXPECT_EQ(flow.selected(), 0);
  flow.picked(std::nullopt);
  EXPECT_TRUE(flow.done());
  EXPECT_FALSE(flow.picking());
}

TEST(PickerFlow, ALevelChosenStartsWithItsSceneLinksAndAttempt) {
  const std::vector<LevelEntry> entries = bundledEntries();
  ASSERT_GE(entries.size(), 3u);
  PickerFlow flow(entries, 4);
  flow.picked(1);
  EXPECT_FALSE(flow.picking());
  PlayScreenConfig base;
  base.json_path = "summary.json";
  const Parsed<PlayScreenConfig> level = flow.levelConfig(base);
  ASSERT_TRUE(level.ok()) << level.error().toString();
  EXPECT_EQ(level.value().session.scene.name, entries[1].scene_name);
  EXPECT_EQ(level.value().session.scene_path, entries[1].path);
  EXPECT_EQ(level.value().session.first_attempt, 4);
  EXPECT_TRUE(level.value().links.from_picker);
  EXPECT_TRUE(level.value().links.has_next);
  EXPECT_EQ(level.value().json_path, "summary.json");  // the rest comes from the base

  // Free drive (last) has no next level.
  flow.levelEnded(ended(LevelExit::kPicker, 5));
  flow.picked(static_cast<int>(entries.size()) - 1);
  ASSERT_TRUE(entries.back().free_drive);
  EXPECT_FALSE(flow.levelConfig(base).value().links.has_next);
}

TEST(PickerFlow, EscReturnsToThePickerWithTheLevelSelected) {
  PickerFlow flow(bundledEntries(), 1);
  flow.picked(2);
  flow.levelEnded(ended(LevelExit::kPicker, 3));
  EXPECT_TRUE(flow.picking());
  EXPECT_EQ(flow.selected(), 2);
  flow.picked(0);
  // Attempts go on from the last one played, so no recording is overwritten.
  EXPECT_EQ(flow.levelConfig({}).value().session.first_attempt, 4);
}

TEST(PickerFlow, NextOpensTheFollowingLevelWithoutThePicker) {
  const std::vector<LevelEntry> entries = bundledEntries();
  PickerFlow flow(entries, 1);
  flow.picked(0);
  flow.levelEnded(ended(LevelExit::kNextLevel, 1));
  EXPECT_FALSE(flow.picking());
  EXPECT_FALSE(flow.done());
  EXPECT_EQ(flow.selected(), 1);
  const Parsed<PlayScreenConfig> level = flow.levelConfig({});
  EXPECT_EQ(level.value().session.scene_path, entries[1].path);
  EXPECT_EQ(level.value().session.first_attempt, 2);
}

TEST(PickerFlow, QuitInALevelEndsIt) {
  PickerFlow flow(bundledEntries(), 1);
  flow.picked(0);
  flow.levelEnded(ended(LevelExit::kQuit, 1));
  EXPECT_TRUE(flow.done());
}

TEST(PickerFlow, ASceneThatDoesNotLoadIsAnError) {
  std::vector<LevelEntry> entries = {{"no-such-level.json", "Gone", "gone", 1, false, ""}};
  PickerFlow flow(entries, 1);
  flow.picked(0);
  const Parsed<PlayScreenConfig> level = flow.levelConfig({});
  ASSERT_FALSE(level.ok());
  EXPECT_EQ(level.error().file, "no-such-level.json");
}

TEST(PickerFlow, ARowOutsideTheListEndsIt) {
  PickerFlow flow(bundledEntries(), 1);
  flow.picked(99);
  EXPECT_TRUE(flow.done());
}

}  // namespace
}  // namespace cardemo
