#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_json.hpp"
#include "io_test_util.hpp"

namespace cardemo::scene_gates_test {
namespace {

using testing::failsAt;
using testing::replaced;

// Line numbers below refer to this text: the gates are on lines 6 to 9.
constexpr std::string_view kScene = R"({
  "format": "cardemo-scene/1",
  "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
  "parked": [],
  "goal": {"bay": {"x": 20, "y": 0, "heading_deg": 0, "length": 5.5, "width": 2.6},
    "gates": [
      {"name": "left of the cone", "line": [[5, 1], [5, 4]], "direction_deg": 0},
      {"name": "the alley", "box": {"x": 10, "y": 0, "heading_deg": 90, "length": 2, "width": 4}},
      {"name": "any way", "line": [[15, -3], [15, 3]]}
    ]
  }
}
)";

Parsed<Scene> parse(std::string_view text) {
  return parseScene(text, "gates.json");
}

std::string with(std::string_view from, std::string_view to) {
  return replaced(std::string(kScene), from, to);
}

TEST(SceneGates, GatesParseInOrder) {
  const Parsed<Scene> p = parse(kScene);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const std::vector<Gate>& gates = p.value().goal->gates;
  ASSERT_EQ(gates.size(), 3u);
  EXPECT_EQ(gates[0].kind, Gate::Kind::kLine);
  EXPECT_EQ(gates[0].name, "left of the cone");
  EXPECT_EQ(gates[0].from, Eigen::Vector2d(5, 1));
  EXPECT_EQ(gates[0].to, Eigen::Vector2d(5, 4));
  EXPECT_EQ(gates[0].center, Eigen::Vector2d(5, 2.5));
  ASSERT_TRUE(gates[0].direction.has_value());
  EXPECT_EQ(*gates[0].direction, Eigen::Vector2d(1, 0));
  EXPECT_EQ(gates[0].side, -1);  // towards +x is the right of (5, 1) -> (5, 4)
  EXPECT_EQ(gates[1].kind, Gate::Kind::kBox);
  EXPECT_EQ(gates[1].center, Eigen::Vector2d(10, 0));
  // 2 m along heading 90 (y), 4 m across (x); counter-clockwise from local (+x, -y).
  EXPECT_EQ(gates[1].corners[0], Eigen::Vector2d(12, 1));
  EXPECT_EQ(gates[1].corners[2], Eigen::Vector2d(8, -1));
  EXPECT_FALSE(gates[1].direction.has_value());
  EXPECT_FALSE(gates[2].direction.has_value());
  EXPECT_EQ(gates[2].side, 0);
}

// The scene with its gates replaced by an object (still on line 6).
const std::string kWithoutGates = with(R"([
      {"name": "left of the cone", "line": [[5, 1], [5, 4]], "direction_deg": 0},
      {"name": "the alley", "box": {"x": 10, "y": 0, "heading_deg": 90, "length": 2, "width": 4}},
      {"name": "any way", "line": [[15, -3], [15, 3]]}
    ])",
                                       "{}");

TEST(SceneGates, NoGatesByDefault) {
  const Parsed<Scene> p = parse(replaced(kWithoutGates, ",\n    \"gates\": {}", ""));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_TRUE(p.value().goal->gates.empty());
}

TEST(SceneGatesErrors, EachMistakeNamesItsLineAndField) {
  EXPECT_TRUE(failsAt(parse(kWithoutGates), 6, "goal.gates: expected an array, found an object"));
  EXPECT_TRUE(
      failsAt(parse(with("\"name\": \"any way\", ", "")), 9, "goal.gates[2]: missing \"name\""));
  EXPECT_TRUE(
      failsAt(parse(with("\"any way\"", "\"\"")), 9, "goal.gates[2].name: must be 1 to 40 bytes"));
  EXPECT_TRUE(failsAt(parse(with("\"any way\"", "\"" + std::string(41, 'x') + "\"")), 9,
                      "goal.gates[2].name: must be 1 to 40 bytes"));
  EXPECT_TRUE(failsAt(parse(with("\"line\": [[15, -3], [15, 3]]", "\"lines\": 1")), 9,
                      "unknown key \"lines\" in goal.gates[2]"));
  EXPECT_TRUE(failsAt(parse(with(", \"line\": [[15, -3], [15, 3]]", "")), 9,
                      "goal.gates[2]: needs exactly one of \"line\" and \"box\""));
  EXPECT_TRUE(failsAt(
      parse(with("\"line\": [[15, -3], [15, 3]]",
                 "\"line\": [[15, -3], [15, 3]], \"box\": {\"x\": 0, \"y\": 0, \"heading_deg\": 0, "
                 "\"length\": 1, \"width\": 1}")),
      9, "needs exactly one of"));
  EXPECT_TRUE(failsAt(parse(with("[[15, -3], [15, 3]]", "[[15, -3]]")), 9,
                      "goal.gates[2].line: expected [[x, y], [x, y]], found 1 points"));
  EXPECT_TRUE(failsAt(parse(with("[[15, -3], [15, 3]]", "[[15, 3], [15, 3]]")), 9,
                      "goal.gates[2].line: the two ends must differ"));
  EXPECT_TRUE(failsAt(parse(with("[[15, -3], [15, 3]]", "[[15, -3], [15, \"3\"]]")), 9,
                      "goal.gates[2].line[1][1]: expected a number"));
  EXPECT_TRUE(failsAt(parse(with("\"length\": 2", "\"length\": 0")), 8,
                      "goal.gates[1].box.length: must be finite and > 0"));
  EXPECT_TRUE(failsAt(parse(with("\"width\": 4}", "\"width\": 4, \"w\": 1}")), 8,
                      "unknown key \"w\" in goal.gates[1].box"));
  // A direction along the line (here within 10 degrees of it) cannot be crossed.
  EXPECT_TRUE(failsAt(parse(with("\"direction_deg\": 0", "\"direction_deg\": 85")), 7,
                      "goal.gates[0].direction_deg: must cross the line"));
  EXPECT_TRUE(failsAt(parse(with("\"direction_deg\": 0", "\"direction_deg\": \"east\"")), 7,
                      "goal.gates[0].direction_deg: expected a number"));
  EXPECT_TRUE(parse(with("\"direction_deg\": 0", "\"direction_deg\": 79")).ok());
}

TEST(SceneGatesErrors, AtMost64Gates) {
  std::string many;
  for (int i = 0; i < 65; ++i) {
    many += std::string(i ? ", " : "") + R"({"name": "g", "line": [[0, 0], [0, 1]]})";
  }
  const std::string text = with(R"({"name": "any way", "line": [[15, -3], [15, 3]]})", many);
  EXPECT_TRUE(failsAt(parse(text), 6, "goal.gates: at most 64 gates, found 67"));
}

}  // namespace
}  // namespace cardemo::scene_gates_test
