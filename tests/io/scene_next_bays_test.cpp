#include <gtest/gtest.h>

#include <string>

#include "io/scene_json.hpp"
#include "io_test_util.hpp"

namespace cardemo::scene_next_bays_test {
namespace {

using testing::failsAt;
using testing::replaced;

// Line numbers below refer to this text: the next bays are on lines 6 to 9.
constexpr std::string_view kScene = R"({
  "format": "cardemo-scene/1",
  "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
  "parked": [],
  "goal": {"bay": {"x": 20, "y": 0, "heading_deg": 0, "length": 5.5, "width": 2.6},
    "next_bays": [
      {"x": 30, "y": 5, "heading_deg": 90, "length": 5, "width": 2.5},
      {"x": -10, "y": 0, "heading_deg": 180, "length": 6, "width": 3}
    ],
    "time_limit": 90
  }
}
)";

Parsed<Scene> parse(std::string_view text) {
  return parseScene(text, "chain.json");
}

std::string with(std::string_view from, std::string_view to) {
  return replaced(std::string(kScene), from, to);
}

TEST(SceneNextBays, BaysParseInOrderAfterTheFirst) {
  const Parsed<Scene> p = parse(kScene);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const Goal& goal = *p.value().goal;
  EXPECT_EQ(goal.bay.center, Eigen::Vector2d(20, 0));
  ASSERT_EQ(goal.next_bays.size(), 2u);
  EXPECT_EQ(goal.next_bays[0].center, Eigen::Vector2d(30, 5));
  EXPECT_EQ(goal.next_bays[0].heading_deg, 90.0);
  EXPECT_EQ(goal.next_bays[0].length, 5.0);
  EXPECT_EQ(goal.next_bays[0].width, 2.5);
  EXPECT_EQ(goal.next_bays[1].center, Eigen::Vector2d(-10, 0));
  EXPECT_EQ(goal.next_bays[1].heading_deg, 180.0);
}

TEST(SceneNextBays, NoneByDefaultAndAnEmptyListIsOneBay) {
  const std::string bays = R"([
      {"x": 30, "y": 5, "heading_deg": 90, "length": 5, "width": 2.5},
      {"x": -10, "y": 0, "heading_deg": 180, "length": 6, "width": 3}
    ])";
  const Parsed<Scene> empty = parse(with(bays, "[]"));
  ASSERT_TRUE(empty.ok()) << empty.error().toString();
  EXPECT_TRUE(empty.value().goal->next_bays.empty());
  const Parsed<Scene> none = parse(with("\"next_bays\": " + bays + ",", ""));
  ASSERT_TRUE(none.ok()) << none.error().toString();
  EXPECT_TRUE(none.value().goal->next_bays.empty());
}

TEST(SceneNextBaysErrors, EachMistakeNamesItsLineAndField) {
  const std::string as_object =
      replaced(with("\"next_bays\": [", "\"next_bays\": {\"a\": ["), "    ],\n    \"time_limit\"",
               "    ]},\n    \"time_limit\"");
  EXPECT_TRUE(failsAt(parse(as_object), 6, "goal.next_bays: expected an array, found an object"));
  EXPECT_TRUE(failsAt(parse(with("\"width\": 3}", "\"width\": 3, \"id\": \"B\"}")), 8,
                      "unknown key \"id\" in goal.next_bays[1]"));
  EXPECT_TRUE(
      failsAt(parse(with(", \"width\": 3}", "}")), 8, "goal.next_bays[1]: missing \"width\""));
  EXPECT_TRUE(failsAt(parse(with("\"length\": 5,", "\"length\": 0,")), 7,
                      "goal.next_bays[0].length: must be finite and > 0"));
  EXPECT_TRUE(failsAt(parse(with("\"y\": 5,", "\"y\": \"5\",")), 7,
                      "goal.next_bays[0].y: expected a number"));
  EXPECT_TRUE(failsAt(parse(with("\"x\": -10,", "\"x\": 1e10,")), 8, "goal.next_bays[1].x"));
  EXPECT_TRUE(failsAt(
      parse(with("{\"x\": -10, \"y\": 0, \"heading_deg\": 180, \"length\": 6, \"width\": 3}", "7")),
      8, "goal.next_bays[1]: expected an object, found a number"));
}

TEST(SceneNextBaysErrors, AtMost15Bays) {
  const std::string bay = R"({"x": 1, "y": 2, "heading_deg": 0, "length": 5, "width": 2})";
  std::string many = bay;
  for (int i = 1; i < 14; ++i) many += ", " + bay;
  const std::string second = R"({"x": -10, "y": 0, "heading_deg": 180, "length": 6, "width": 3})";
  const Parsed<Scene> fifteen = parse(with(second, many));
  ASSERT_TRUE(fifteen.ok()) << fifteen.error().toString();
  EXPECT_EQ(fifteen.value().goal->next_bays.size(), 15u);
  EXPECT_TRUE(failsAt(parse(with(second, many + ", " + bay)), 6,
                      "goal.next_bays: at most 15 bays, found 16"));
}

}  // namespace
}  // namespace cardemo::scene_next_bays_test
