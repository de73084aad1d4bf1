#include "play/level_list.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace cardemo {
namespace {

namespace fs = std::filesystem;

std::string levelScene(const std::string& name, int order, const std::string& title) {
  return R"({"format": "cardemo-scene/1", "name": ")" + name +
         R"(", "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
  "parked": [], "level": {"order": )" +
         std::to_string(order) + R"(, "title": ")" + title + R"("}})";
}

TEST(LevelList, BundledLevelsInOrderThenFreeDrive) {
  std::vector<std::string> warnings;
  const std::vector<LevelEntry> e =
      listLevels(std::string(CARDEMO_SOURCE_DIR) + "/assets", warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(e.size(), 11u);
  EXPECT_EQ(e[0].title, "Straight in");
  EXPECT_EQ(e[1].title, "Reverse bay");
  EXPECT_EQ(e[2].title, "Parallel parking");
  EXPECT_EQ(e[3].title, "Tight garage");
  EXPECT_EQ(e[4].title, "Slalom");
  EXPECT_EQ(e[5].title, "Three-point turn");
  EXPECT_EQ(e[6].title, "Narrow alley");
  EXPECT_EQ(e[7].title, "Angled bay");
  EXPECT_EQ(e[8].title, "Behind the cones");
  EXPECT_EQ(e[9].title, "Two bays against the clock");
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(e[static_cast<std::size_t>(i)].order, i + 1);
    EXPECT_FALSE(e[static_cast<std::size_t>(i)].free_drive);
  }
  // Every level says what to do (the picker shows it under the selected title).
  for (const LevelEntry& level : e) EXPECT_FALSE(level.task.empty()) << level.title;
  EXPECT_NE(e[1].task.find("reverse into the bay"), std::string::npos) << e[1].task;
  EXPECT_NE(e[1].task.find("facing out"), std::string::npos) << e[1].task;
  EXPECT_TRUE(e[10].free_drive);
  EXPECT_EQ(e[10].title, "Free drive");
  EXPECT_NE(e[10].path.find("parking-lot.json"), std::string::npos);
}

TEST(LevelList, NextLevelStopsAtTheLastLevelAndNeverLeadsToFreeDrive) {
  const std::vector<LevelEntry> e{{"a.json", "A", "a", 1, false, "Park"},
                                  {"b.json", "B", "b", 2, false, ""},
                                  {"lot.json", "Free drive", "parking-lot", 0, true, "Drive"}};
  EXPECT_EQ(nextLevel(e, 0), std::optional<std::size_t>(1));
  EXPECT_EQ(nextLevel(e, 1), std::nullopt);  // the last level: free drive is not "next"
  EXPECT_EQ(nextLevel(e, 2), std::nullopt);  // free drive has no next level
  EXPECT_EQ(nextLevel(e, 7), std::nullopt);  // out of range
  std::vector<std::string> warnings;
  const std::vector<LevelEntry> bundled =
      listLevels(std::string(CARDEMO_SOURCE_DIR) + "/assets", warnings);
  ASSERT_EQ(bundled.size(), 11u);
  EXPECT_EQ(nextLevel(bundled, 0), std::optional<std::size_t>(1));
  EXPECT_EQ(nextLevel(bundled, 5), std::optional<std::size_t>(6));
  EXPECT_EQ(nextLevel(bundled, 6), std::optional<std::size_t>(7));
  EXPECT_EQ(nextLevel(bundled, 7), std::optional<std::size_t>(8));
  EXPECT_EQ(nextLevel(bundled, 8), std::optional<std::size_t>(9));
  EXPECT_EQ(nextLevel(bundled, 9), std::nullopt);
}

// Progress counts the levels (not free drive), those with a best score and their stars.
TEST(LevelList, ProgressCountsParkedLevelsAndTheirStars) {
  const std::vector<LevelEntry> e{{"a.json", "A", "a", 1, false, ""},
                                  {"b.json", "B", "b", 2, false, ""},
                                  {"c.json", "C", "c", 3, false, ""},
                                  {"lot.json", "Free drive", "parking-lot", 0, true, ""}};
  BestScores best;
  EXPECT_EQ(progressText(levelProgress(e, best)), "0 / 3 levels parked     \xE2\x98\x85 0 / 9");
  ASSERT_TRUE(best.offer("a", {100, 1.0, 0, 3}));
  ASSERT_TRUE(best.offer("c", {200, 2.0, 10, 1}));
  ASSERT_TRUE(best.offer("parking-lot", {300, 3.0, 0, 3}));  // free drive: not a level
  const LevelProgress p = levelProgress(e, best);
  EXPECT_EQ(p.levels, 3);
  EXPECT_EQ(p.parked, 2);
  EXPECT_EQ(p.stars, 4);
  EXPECT_EQ(p.possibleStars(), 9);
  EXPECT_EQ(progressText(p), "2 / 3 levels parked     \xE2\x98\x85 4 / 9");
  EXPECT_EQ(progressText(levelProgress({}, best)), "");
}

TEST(LevelList, ScenesWithoutLevelAreLeftOutAndBrokenOnesWarned) {
  const fs::path dir = fs::temp_directory_path() / ("cardemo_levels_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes" / "levels");
  std::ofstream(dir / "scenes" / "levels" / "b.json") << levelScene("b", 2, "Second");
  std::ofstream(dir / "scenes" / "levels" / "a.json") << levelScene("a", 2, "Also second");
  std::ofstream(dir / "scenes" / "levels" / "c.json") << levelScene("c", 1, "First");
  std::ofstream(dir / "scenes" / "levels" / "test-only.json")
      << R"({"format": "cardemo-scene/1", "player": {"x": 0, "y": 0, "heading_deg": 0,
            "length": 4.5, "width": 1.8}, "parked": []})";
  std::ofstream(dir / "scenes" / "levels" / "broken.json") << "{";
  std::ofstream(dir / "scenes" / "levels" / "notes.txt") << "not a scene";
  std::vector<std::string> warnings;
  const std::vector<LevelEntry> e = listLevels(dir.string(), warnings);
  ASSERT_EQ(e.size(), 3u);  // no parking-lot.json here: no free drive
  EXPECT_EQ(e[0].scene_name, "c");
  EXPECT_EQ(e[1].scene_name, "a");  // same order: by title
  EXPECT_EQ(e[2].scene_name, "b");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("broken.json:"), std::string::npos) << warnings[0];
  fs::remove_all(dir);
}

TEST(LevelList, MissingFolderGivesNothing) {
  std::vector<std::string> warnings;
  EXPECT_TRUE(listLevels("/nonexistent/cardemo/assets", warnings).empty());
  EXPECT_TRUE(warnings.empty());
}

TEST(LevelList, MoveSelectionWraps) {
  EXPECT_EQ(moveSelection(0, -1, 5), 4);
  EXPECT_EQ(moveSelection(4, 1, 5), 0);
  EXPECT_EQ(moveSelection(2, 1, 5), 3);
  EXPECT_EQ(moveSelection(0, 1, 0), 0);
}

}  // namespace
}  // namespace cardemo
