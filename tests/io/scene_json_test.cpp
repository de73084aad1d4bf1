#include "io/scene_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "io_test_util.hpp"

namespace cardemo {
namespace {

using testing::failsAt;
using testing::replaced;

// Line numbers below refer to this text.
constexpr std::string_view kScene = R"({
  "format": "cardemo-scene/1",
  "name": "lot",
  "bounds": {"min": [-60, -40], "max": [60, 40]},
  "player": {
    "x": 1,
    "y": 2,
    "heading_deg": 0,
    "length": 4.5,
    "width": 1.8,
    "health": 80,
    "speed": 3
  },
  "parked": [
    {"id": "A1", "x": 10, "y": 5, "heading_deg": 90, "length": 4.5, "width": 1.8},
    {"id": "A2", "x": -10, "y": 5, "heading_deg": 30, "length": 4, "width": 2},
    {"id": "A3", "x": 0, "y": -20, "heading_deg": 180, "length": 5, "width": 2.2}
  ],
  "obstacles": [
    {"id": "kerb", "points": [[0, 0], [0, 1], [3, 1], [3, 0]]}
  ]
}
)";

Parsed<Scene> parseSampleScene(std::string_view text) {
  return parseScene(text, "lot.json");
}

std::string sceneWith(std::string_view from, std::string_view to) {
  return replaced(std::string(kScene), from, to);
}

TEST(SceneJson, ValidSceneParsesIntoTheRightValues) {
  const Parsed<Scene> p = parseSampleScene(kScene);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const Scene& s = p.value();
  EXPECT_EQ(s.name, "lot");
  ASSERT_TRUE(s.bounds.has_value());
  EXPECT_EQ(s.bounds->min, Eigen::Vector2d(-60, -40));
  EXPECT_EQ(s.bounds->max, Eigen::Vector2d(60, 40));
  EXPECT_EQ(s.player.position, Eigen::Vector2d(1, 2));
  EXPECT_EQ(s.player.heading_deg, 0.0);
  EXPECT_EQ(s.player.length, 4.5);
  EXPECT_EQ(s.player.width, 1.8);
  EXPECT_EQ(s.player.health, 80);
  EXPECT_EQ(s.player.speed, 3.0);
  ASSERT_EQ(s.parked.size(), 3u);
  EXPECT_EQ(s.parked[0].id, "A1");
  EXPECT_EQ(s.parked[0].heading_deg, 90.0);
  EXPECT_EQ(s.parked[0].box.center, Eigen::Vector2d(10, 5));
  EXPECT_EQ(s.parked[0].box.half, Eigen::Vector2d(2.25, 0.9));
  EXPECT_EQ(s.parked[1].id, "A2");
  EXPECT_EQ(s.parked[1].box.half, Eigen::Vector2d(2, 1));
  EXPECT_NEAR(s.parked[1].box.axis.x(), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(s.parked[1].box.axis.y(), 0.5, 1e-15);
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_EQ(s.obstacles[0].id, "kerb");
  EXPECT_EQ(s.obstacles[0].polygon.count, 4);
}

TEST(SceneJson, Heading90GivesExactAxis) {
  const Parsed<Scene> p = parseSampleScene(kScene);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().parked[0].box.axis, Eigen::Vector2d(0, 1));  // exact, not 6e-17
  EXPECT_EQ(p.value().parked[2].box.axis, Eigen::Vector2d(-1, 0));
}

TEST(SceneJson, ClockwiseObstacleIsStoredCounterClockwise) {
  const Parsed<Scene> p = parseSampleScene(kScene);
  ASSERT_TRUE(p.ok());
  const ConvexPolygon& poly = p.value().obstacles[0].polygon;
  double twice_area = 0;
  for (int i = 0; i < poly.count; ++i) {
    const Eigen::Vector2d& a = poly.vertex(i);
    const Eigen::Vector2d& b = poly.vertex((i + 1) % poly.count);
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_DOUBLE_EQ(twice_area, 6.0);
}

TEST(SceneJson, MinimalSceneUsesDefaults) {
  const Parsed<Scene> p = parseScene(R"({"format": "cardemo-scene/1",
    "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8}, "parked": []})",
                                     "scenes/empty-lot.json");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().name, "empty-lot");  // name defaults to the file stem
  EXPECT_FALSE(p.value().bounds.has_value());
  EXPECT_EQ(p.value().player.health, 100);
  EXPECT_EQ(p.value().player.speed, 0.0);
  EXPECT_TRUE(p.value().parked.empty());
  EXPECT_TRUE(p.value().obstacles.empty());
}

TEST(SceneJson, StdinSceneWithoutNameIsNamedScene) {
  const Parsed<Scene> p = parseScene(
      R"({"format": "cardemo-scene/1", "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 1, "width": 1}, "parked": []})",
      "-");
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().name, "scene");
}

TEST(SceneJson, NegativeSpeedWithinLimitIsAccepted) {
  const Parsed<Scene> p = parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": -1000"));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().player.speed, -1000.0);
}

TEST(SceneJson, MaxSpeedIsOptionalAndPositive) {
  EXPECT_EQ(parseSampleScene(kScene).value().player.max_speed,
            std::numeric_limits<double>::infinity());
  const Parsed<Scene> p =
      parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": 3, \"max_speed\": 5.5"));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().player.max_speed, 5.5);
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": 3, \"max_speed\": 0")),
                      12, "player.max_speed: must be > 0"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": 3, \"max_speed\": 2000")), 12,
              "player.max_speed: must be finite with |speed| <= 1000"));
}

TEST(SceneJson, IntegralFloatHealthIsAccepted) {
  const Parsed<Scene> p = parseSampleScene(sceneWith("\"health\": 80", "\"health\": 8e1"));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().player.health, 80);
}

TEST(SceneJson, ErrorStringNamesFileLineAndField) {
  const Parsed<Scene> p = parseSampleScene(sceneWith("\"width\": 2}", "\"width\": 0}"));
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().toString(), "lot.json:16: parked[1].width: must be finite and > 0");
}

TEST(SceneJson, BundledScenesParse) {
  for (const char* name : {"parking-lot", "garage", "runway", "large-lot"}) {
    const Parsed<Scene> p =
        loadScene(std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/" + name + ".json");
    ASSERT_TRUE(p.ok()) << p.error().toString();
    EXPECT_FALSE(p.value().parked.empty()) << name;
  }
}

TEST(SceneJson, BundledLevelsHaveAGoalAndAnOrder) {
  int order = 0;
  for (const char* name : {"level-1-straight", "level-2-reverse", "level-3-parallel",
                           "level-4-garage", "level-5-slalom", "level-6-turn"}) {
    const Parsed<Scene> p =
        loadScene(std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/levels/" + name + ".json");
    ASSERT_TRUE(p.ok()) << p.error().toString();
    ASSERT_TRUE(p.value().goal.has_value()) << name;
    ASSERT_TRUE(p.value().level.has_value()) << name;
    EXPECT_EQ(p.value().level->order, ++order) << name;
    EXPECT_FALSE(p.value().markings.empty()) << name;
    EXPECT_FALSE(p.value().obstacles.empty()) << name;
  }
}

// --- malformed input, one class per test ---

TEST(SceneJsonErrors, EmptyFile) {
  EXPECT_TRUE(failsAt(parseSampleScene(""), 1, "empty scene file"));
}

TEST(SceneJsonErrors, WhitespaceOnlyFile) {
  EXPECT_TRUE(failsAt(parseSampleScene("\n \n\t\n"), 1, "empty scene file"));
}

TEST(SceneJsonErrors, GarbageBytes) {
  EXPECT_TRUE(failsAt(parseSampleScene("\xff\xfe\x01garbage"), 1, "invalid JSON"));
}

TEST(SceneJsonErrors, GarbageBytesOnALaterLine) {
  EXPECT_TRUE(failsAt(parseSampleScene("{\n  \"format\": \"cardemo-scene/1\",\n  \xc3\x28\n}"), 3,
                      "invalid JSON"));
}

TEST(SceneJsonErrors, InvalidUtf8InsideAString) {
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("\"lot\"", "\"l\xff\"")), 3, "invalid JSON in name"));
}

TEST(SceneJsonErrors, BinaryWithNulByte) {
  std::string text(kScene);
  text[text.find("\"A2\"")] = '\0';
  EXPECT_TRUE(failsAt(parseSampleScene(text), 16, "NUL byte"));
}

TEST(SceneJsonErrors, TruncatedJson) {
  const std::string text(kScene.substr(0, kScene.find("\"A2\"")));
  EXPECT_TRUE(failsAt(parseSampleScene(text), 16, "invalid JSON in parked[1]"));
}

TEST(SceneJsonErrors, TruncatedAfterNewline) {
  const std::string text(kScene.substr(0, kScene.find("  \"parked\"")));
  EXPECT_TRUE(failsAt(parseSampleScene(text), 13, "unexpected end of input"));
}

TEST(SceneJsonErrors, DeepNesting) {
  EXPECT_TRUE(failsAt(parseSampleScene(std::string(100000, '[')), 1, "nesting deeper than 64"));
  EXPECT_TRUE(failsAt(parseSampleScene("\n" + std::string(100000, '{')), 2, "invalid JSON"));
  EXPECT_TRUE(failsAt(
      parseSampleScene(sceneWith(
          "\"x\": 1,", "\"x\": " + std::string(70, '[') + "1" + std::string(70, ']') + ",")),
      6, "nesting deeper than 64"));
}

TEST(SceneJsonErrors, NestingOf64IsNotANestingError) {
  const std::string text = std::string(64, '[') + std::string(64, ']');
  EXPECT_TRUE(failsAt(parseSampleScene(text), 1, "must be a JSON object, found an array"));
  EXPECT_TRUE(failsAt(parseSampleScene("[" + text + "]"), 1, "nesting deeper than 64"));
}

TEST(SceneJsonErrors, NaNLiteral) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"x\": 1,", "\"x\": NaN,")), 6,
                      "invalid JSON in player.x"));
}

TEST(SceneJsonErrors, InfinityLiteral) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"y\": 2,", "\"y\": Infinity,")), 7,
                      "invalid JSON in player.y"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("\"y\": 2,", "\"y\": -Infinity,")), 7, "invalid JSON"));
}

TEST(SceneJsonErrors, HugeNumberIsNotFinite) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"x\": 1,", "\"x\": 1e999,")), 6,
                      "player.x: must be finite"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"width\": 1.8,", "\"width\": -1e999,")), 10,
                      "player.width: must be finite"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"x\": 10,", "\"x\": 1e400,")), 15,
                      "parked[0].x: must be finite"));
}

TEST(SceneJsonErrors, HugeIntegerLiteral) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"x\": 1,", "\"x\": 99999999999999999999999,")),
                      6, "player.x: must be finite with |value| <= 1e9"));
}

TEST(SceneJsonErrors, CoordinateTooLarge) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"y\": 2,", "\"y\": -2e9,")), 7,
                      "player.y: must be finite"));
}

TEST(SceneJsonErrors, WrongFormatString) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("cardemo-scene/1", "cardemo-scene/2")), 2,
                      "format: expected \"cardemo-scene/1\", found \"cardemo-scene/2\""));
}

TEST(SceneJsonErrors, FormatOfWrongType) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"cardemo-scene/1\"", "1")), 2,
                      "format: expected a string, found a number"));
}

TEST(SceneJsonErrors, MissingFormat) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("  \"format\": \"cardemo-scene/1\",\n", "")), 1,
                      "missing \"format\""));
}

TEST(SceneJsonErrors, MissingPlayerField) {
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("    \"y\": 2,\n", "")), 5, "player: missing \"y\""));
}

TEST(SceneJsonErrors, MissingParked) {
  EXPECT_TRUE(failsAt(parseSampleScene(R"({"format": "cardemo-scene/1",
    "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8}})"),
                      1, "missing \"parked\""));
}

TEST(SceneJsonErrors, MissingPlayer) {
  EXPECT_TRUE(
      failsAt(parseSampleScene(R"({"format": "cardemo-scene/1"})"), 1, "missing \"player\""));
}

TEST(SceneJsonErrors, UnknownKeyTopLevel) {
  EXPECT_TRUE(failsAt(
      parseSampleScene(sceneWith("  \"name\": \"lot\",", "  \"name\": \"lot\",\n  \"nmae\": 1,")),
      4, "unknown key \"nmae\" in scene"));
}

TEST(SceneJsonErrors, UnknownKeyNested) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"health\"", "\"helth\"")), 11,
                      "unknown key \"helth\" in player"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"width\": 2}", "\"width\": 2, \"colour\": 1}")),
                      16, "unknown key \"colour\" in parked[1]"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("\"max\": [60, 40]", "\"max\": [60, 40], \"mid\": 0")), 4,
              "unknown key \"mid\" in bounds"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("{\"id\": \"kerb\"", "{\"id\": \"kerb\", \"z\": 1")), 20,
              "unknown key \"z\" in obstacles[0]"));
}

TEST(SceneJsonErrors, WrongType) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"x\": 1,", "\"x\": \"1\",")), 6,
                      "player.x: expected a number, found a string"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("{\"min\": [-60, -40], \"max\": [60, 40]}", "[-60, 60]")),
              4, "bounds: expected an object, found an array"));
  EXPECT_TRUE(failsAt(parseSampleScene(R"({"format": "cardemo-scene/1",
      "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
      "parked": {}})"),
                      3, "parked: expected an array, found an object"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"A3\"", "\"id\": 3")), 17,
                      "parked[2].id: expected a string, found a number"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"name\": \"lot\"", "\"name\": null")), 3,
                      "name: expected a string, found null"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": true")), 12,
                      "player.speed: expected a number, found a boolean"));
}

TEST(SceneJsonErrors, RootNotAnObject) {
  EXPECT_TRUE(failsAt(parseSampleScene("\n[1, 2]"), 2, "must be a JSON object"));
  EXPECT_TRUE(failsAt(parseSampleScene("\"scene\""), 1, "must be a JSON object, found a string"));
}

TEST(SceneJsonErrors, NegativeLength) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"length\": 4.5,\n", "\"length\": -4.5,\n")), 9,
                      "player.length: must be finite and > 0"));
}

TEST(SceneJsonErrors, ZeroWidth) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"width\": 1.8,", "\"width\": 0,")), 10,
                      "player.width: must be finite and > 0"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"width\": 2}", "\"width\": -0.0}")), 16,
                      "parked[1].width: must be finite and > 0"));
}

TEST(SceneJsonErrors, AbsurdlyLongCar) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"length\": 5,", "\"length\": 1e5,")), 17,
                      "parked[2].length: must be at most 10000 m"));
}

TEST(SceneJsonErrors, DuplicateId) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"A2\"", "\"id\": \"A1\"")), 16,
                      "parked[1].id: duplicate id \"A1\" (also parked[0])"));
}

TEST(SceneJsonErrors, DuplicateIdAcrossObstacles) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"kerb\"", "\"id\": \"A3\"")), 20,
                      "obstacles[0].id: duplicate id \"A3\" (also parked[2])"));
}

TEST(SceneJsonErrors, EmptyOrUnprintableId) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"A2\"", "\"id\": \"\"")), 16,
                      "must not be empty"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"A2\"", "\"id\": \"A\\n2\"")), 16,
                      "must not contain control characters"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"id\": \"A2\"", "\"id\": \"A2 \"")), 16,
                      "must not start or end with a space"));
}

TEST(SceneJsonErrors, MissingId) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("{\"id\": \"A3\", ", "{")), 17,
                      "parked[2]: missing \"id\""));
}

TEST(SceneJsonErrors, DuplicateKey) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"y\": 2,", "\"y\": 2, \"x\": 3,")), 7,
                      "duplicate key \"x\" in player"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("  \"name\": \"lot\",",
                                                 "  \"name\": \"lot\",\n  \"name\": \"x\",")),
                      4, "duplicate key \"name\" in scene"));
}

TEST(SceneJsonErrors, NonConvexObstacle) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("[[0, 0], [0, 1], [3, 1], [3, 0]]",
                                                 "[[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]]")),
                      20, "obstacles[0].points: "));
}

TEST(SceneJsonErrors, DegenerateObstacle) {
  EXPECT_TRUE(failsAt(
      parseSampleScene(sceneWith("[[0, 0], [0, 1], [3, 1], [3, 0]]", "[[0, 0], [1, 1], [2, 2]]")),
      20, "obstacles[0].points: "));
}

TEST(SceneJsonErrors, TooManyPoints) {
  std::string points = "[";
  for (int i = 0; i < 17; ++i) {
    const double a = 2 * 3.141592653589793 * i / 17;
    points +=
        (i ? ", [" : "[") + std::to_string(std::cos(a)) + ", " + std::to_string(std::sin(a)) + "]";
  }
  points += "]";
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("[[0, 0], [0, 1], [3, 1], [3, 0]]", points)), 20,
                      "obstacles[0].points: expected 3 to 16 points, found 17"));
}

TEST(SceneJsonErrors, TooFewPoints) {
  EXPECT_TRUE(
      failsAt(parseSampleScene(sceneWith("[[0, 0], [0, 1], [3, 1], [3, 0]]", "[[0, 0], [0, 1]]")),
              20, "expected 3 to 16 points, found 2"));
}

TEST(SceneJsonErrors, PointNotAPair) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("[3, 1]", "[3, 1, 2]")), 20,
                      "obstacles[0].points[2]: expected [x, y], found 3 values"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("[3, 1]", "\"3, 1\"")), 20,
                      "obstacles[0].points[2]: expected an array, found a string"));
}

TEST(SceneJsonErrors, BoundsMinNotBelowMax) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"max\": [60, 40]", "\"max\": [60, -40]")), 4,
                      "bounds: min must be less than max"));
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"max\": [60, 40]", "\"max\": [-70, 40]")), 4,
                      "bounds: min must be less than max"));
}

TEST(SceneJsonErrors, BoundsMissingMax) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith(", \"max\": [60, 40]", "")), 4,
                      "bounds: missing \"max\""));
}

TEST(SceneJsonErrors, HealthZero) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"health\": 80", "\"health\": 0")), 11,
                      "player.health: must be > 0"));
}

TEST(SceneJsonErrors, HealthNegative) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"health\": 80", "\"health\": -5")), 11,
                      "player.health: must be > 0"));
}

TEST(SceneJsonErrors, HealthNotAnInteger) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"health\": 80", "\"health\": 80.5")), 11,
                      "player.health: must be an integer"));
}

TEST(SceneJsonErrors, HealthTooLarge) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"health\": 80", "\"health\": 1000001")), 11,
                      "player.health: must be at most 1000000"));
}

TEST(SceneJsonErrors, SpeedTooLarge) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"speed\": 3", "\"speed\": 1000.5")), 12,
                      "player.speed: must be finite with |speed| <= 1000"));
}

TEST(SceneJsonErrors, CommentsAreNotJson) {
  EXPECT_TRUE(failsAt(
      parseSampleScene(sceneWith("  \"name\": \"lot\",", "  // a comment\n  \"name\": \"lot\",")),
      3, "invalid JSON"));
}

TEST(SceneJsonErrors, TrailingData) {
  EXPECT_TRUE(failsAt(parseSampleScene(std::string(kScene) + "\n{}"), 24, "invalid JSON"));
}

TEST(SceneJsonErrors, TrailingComma) {
  EXPECT_TRUE(failsAt(parseSampleScene(sceneWith("\"speed\": 3\n", "\"speed\": 3,\n")), 13,
                      "invalid JSON"));
}

TEST(SceneJsonErrors, MissingFileReportsLineZero) {
  const Parsed<Scene> p = loadScene("/nonexistent/cardemo/lot.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().line, 0);
  EXPECT_NE(p.error().message.find("cannot open"), std::string::npos);
}

// --- goal, level and markings ---

// Line numbers below refer to this text (the base scene's closing brace replaced).
std::string withGoal(std::string_view goal_lines) {
  std::string text(kScene);
  const auto end = text.rfind("]\n}");
  return text.substr(0, end) + "],\n" + std::string(goal_lines) + "\n}\n";
}

// Starts on line 22.
constexpr std::string_view kGoal = R"(  "goal": {
    "bay": {"x": 20, "y": -5, "heading_deg": 90, "length": 5.5, "width": 2.6},
    "position_tolerance": 0.4,
    "heading_tolerance_deg": 6,
    "either_direction": true,
    "max_speed": 0.25,
    "par_time": 15,
    "time_limit": 60
  },
  "level": {"order": 2, "title": "Reverse bay"},
  "markings": [
    {"type": "line", "from": [18.7, -7.75], "to": [18.7, -2.25], "width": 0.12},
    {"type": "arrow", "from": [0, 0], "to": [0, 3]}
  ])";

TEST(SceneJsonGoal, FullGoalParsesIntoTheRightValues) {
  const Parsed<Scene> p = parseSampleScene(withGoal(kGoal));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const Scene& s = p.value();
  ASSERT_TRUE(s.goal.has_value());
  const Goal& g = *s.goal;
  EXPECT_EQ(g.bay.center, Eigen::Vector2d(20, -5));
  EXPECT_EQ(g.bay.heading_deg, 90.0);
  EXPECT_EQ(g.bay.length, 5.5);
  EXPECT_EQ(g.bay.width, 2.6);
  EXPECT_EQ(g.position_tolerance, 0.4);
  EXPECT_EQ(g.heading_tolerance_deg, 6.0);
  EXPECT_TRUE(g.either_direction);
  EXPECT_EQ(g.max_speed, 0.25);
  EXPECT_EQ(g.par_time, 15.0);
  EXPECT_EQ(g.time_limit, 60.0);
  ASSERT_TRUE(s.level.has_value());
  EXPECT_EQ(s.level->order, 2);
  EXPECT_EQ(s.level->title, "Reverse bay");
  EXPECT_EQ(s.level->task, "");  // optional
  ASSERT_EQ(s.markings.size(), 2u);
  EXPECT_EQ(s.markings[0].kind, Marking::Kind::kLine);
  EXPECT_EQ(s.markings[0].from, Eigen::Vector2d(18.7, -7.75));
  EXPECT_EQ(s.markings[0].to, Eigen::Vector2d(18.7, -2.25));
  EXPECT_EQ(s.markings[0].width, 0.12);
  EXPECT_EQ(s.markings[1].kind, Marking::Kind::kArrow);
  EXPECT_EQ(s.markings[1].width, Marking{}.width);
}

TEST(SceneJsonGoal, SceneWithoutGoalHasNone) {
  const Parsed<Scene> p = parseSampleScene(kScene);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_FALSE(p.value().goal.has_value());
  EXPECT_FALSE(p.value().level.has_value());
  EXPECT_TRUE(p.value().markings.empty());
}

TEST(SceneJsonGoal, OnlyTheBayIsRequired) {
  const Parsed<Scene> p = parseSampleScene(withGoal(
      R"(  "goal": {"bay": {"x": 1, "y": 2, "heading_deg": 0, "length": 5, "width": 2.5}})"));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const Goal& g = *p.value().goal;
  EXPECT_EQ(g.position_tolerance, Goal{}.position_tolerance);
  EXPECT_EQ(g.heading_tolerance_deg, Goal{}.heading_tolerance_deg);
  EXPECT_EQ(g.max_speed, Goal{}.max_speed);
  EXPECT_EQ(g.hold_time, 0.5);
  EXPECT_FALSE(g.either_direction);
  EXPECT_FALSE(g.par_time.has_value());
  EXPECT_FALSE(g.time_limit.has_value());
}

std::string goalWith(std::string_view from, std::string_view to) {
  return withGoal(replaced(std::string(kGoal), from, to));
}

TEST(SceneJsonGoalErrors, UnknownKeyInGoal) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"max_speed\"", "\"max_sped\"")), 27,
                      "unknown key \"max_sped\" in goal"));
}

TEST(SceneJsonGoalErrors, UnknownKeyInBay) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"x\": 20", "\"xx\": 20")), 23,
                      "unknown key \"xx\" in goal.bay"));
}

TEST(SceneJsonGoalErrors, MissingBay) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith(
                          "\"bay\": {\"x\": 20, \"y\": -5, \"heading_deg\": 90, \"length\": 5.5, "
                          "\"width\": 2.6},",
                          "")),
                      22, "goal: missing \"bay\""));
}

TEST(SceneJsonGoalErrors, BayWidthZero) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"width\": 2.6", "\"width\": 0")), 23,
                      "goal.bay.width: must be finite and > 0"));
}

TEST(SceneJsonGoalErrors, ToleranceZeroOrNegative) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("0.4", "0")), 24,
                      "goal.position_tolerance: must be finite, > 0"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("0.4", "-1")), 24,
                      "goal.position_tolerance: must be finite, > 0"));
}

TEST(SceneJsonGoalErrors, HeadingToleranceAbove180) {
  EXPECT_TRUE(failsAt(
      parseSampleScene(goalWith("\"heading_tolerance_deg\": 6", "\"heading_tolerance_deg\": 181")),
      25, "goal.heading_tolerance_deg: must be finite, > 0 and at most 180"));
}

TEST(SceneJsonGoalErrors, EitherDirectionMustBeBool) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("true", "1")), 26,
                      "goal.either_direction: expected a boolean"));
}

TEST(SceneJsonGoalErrors, MaxSpeedAndTimesAreValidated) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("0.25", "\"slow\"")), 27,
                      "goal.max_speed: expected a number"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"par_time\": 15", "\"par_time\": 0")), 28,
                      "goal.par_time: must be finite, > 0"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"time_limit\": 60", "\"time_limit\": 1e6")), 29,
                      "goal.time_limit: must be finite, > 0 and at most 100000 s"));
}

std::string goalWithHold(std::string_view hold) {
  return goalWith("\"max_speed\": 0.25,",
                  "\"max_speed\": 0.25, \"hold_time\": " + std::string(hold) + ",");
}

TEST(SceneJsonGoal, HoldTimeIsReadAndZeroIsAllowed) {
  for (const auto& [text, value] :
       {std::pair{"1.25", 1.25}, std::pair{"0", 0.0}, std::pair{"59.5", 59.5}}) {
    const Parsed<Scene> p = parseSampleScene(goalWithHold(text));
    ASSERT_TRUE(p.ok()) << text << ": " << p.error().toString();
    EXPECT_EQ(p.value().goal->hold_time, value) << text;
  }
}

TEST(SceneJsonGoalErrors, HoldTimeIsValidated) {
  for (const char* bad : {"-0.1", "60.5", "1e300"}) {
    EXPECT_TRUE(failsAt(parseSampleScene(goalWithHold(bad)), 27,
                        "goal.hold_time: must be finite, >= 0 and at most 60 s"))
        << bad;
  }
  EXPECT_TRUE(
      failsAt(parseSampleScene(goalWithHold("\"long\"")), 27, "goal.hold_time: expected a number"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(goalWithHold("true")), 27, "goal.hold_time: expected a number"));
}

TEST(SceneJsonGoalErrors, HoldTimeMustBeShorterThanTheTimeLimit) {
  const std::string text =
      replaced(replaced(goalWithHold("10"), "\"time_limit\": 60", "\"time_limit\": 10"),
               "\"par_time\": 15", "\"par_time\": 5");
  EXPECT_TRUE(
      failsAt(parseSampleScene(text), 27, "goal.hold_time: must be less than goal.time_limit"));
  const std::string par_ok =
      replaced(replaced(goalWithHold("9.5"), "\"time_limit\": 60", "\"time_limit\": 10"),
               "\"par_time\": 15", "\"par_time\": 5");
  EXPECT_TRUE(parseSampleScene(par_ok).ok()) << parseSampleScene(par_ok).error().toString();
}

TEST(SceneJsonGoalErrors, ParTimeAboveTimeLimit) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"par_time\": 15", "\"par_time\": 61")), 28,
                      "goal.par_time: must not exceed goal.time_limit"));
}

TEST(SceneJsonLevelErrors, OrderMustBeAPositiveInteger) {
  for (const char* bad : {"0", "1.5", "-3", "10001"}) {
    EXPECT_TRUE(
        failsAt(parseSampleScene(goalWith("\"order\": 2", std::string("\"order\": ") + bad)), 31,
                "level.order: must be an integer from 1 to 10000"))
        << bad;
  }
}

TEST(SceneJsonLevelErrors, TitleMustBeShortPrintableText) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"Reverse bay\"", "\"\"")), 31,
                      "level.title: must be 1 to 64"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(goalWith("\"Reverse bay\"", "\"" + std::string(65, 'x') + "\"")), 31,
              "level.title: must be 1 to 64"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"Reverse bay\"", "\"a\\tb\"")), 31,
                      "level.title: must be 1 to 64"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(goalWith("\"order\": 2, ", "")), 31, "level: missing \"order\""));
}

std::string levelWithTask(std::string_view task_json) {
  return goalWith("\"title\": \"Reverse bay\"",
                  "\"title\": \"Reverse bay\", \"task\": " + std::string(task_json));
}

TEST(SceneJsonLevel, TaskIsReadUpTo100Bytes) {
  const Parsed<Scene> p = parseSampleScene(levelWithTask("\"Reverse into the bay, facing out\""));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().level->task, "Reverse into the bay, facing out");
  const std::string longest(100, 'x');
  const Parsed<Scene> q = parseSampleScene(levelWithTask("\"" + longest + "\""));
  ASSERT_TRUE(q.ok()) << q.error().toString();
  EXPECT_EQ(q.value().level->task, longest);
}

TEST(SceneJsonLevelErrors, TaskMustBeShortPrintableText) {
  EXPECT_TRUE(
      failsAt(parseSampleScene(levelWithTask("42")), 31, "level.task: expected a string, found"));
  EXPECT_TRUE(
      failsAt(parseSampleScene(levelWithTask("[\"a\"]")), 31, "level.task: expected a string"));
  for (const std::string& bad :
       {std::string("\"\""), "\"" + std::string(101, 'x') + "\"", std::string("\"two\\nlines\"")}) {
    EXPECT_TRUE(failsAt(parseSampleScene(levelWithTask(bad)), 31,
                        "level.task: must be 1 to 100 bytes without control characters"))
        << bad;
  }
  const Parsed<Scene> p = parseSampleScene(levelWithTask("\"" + std::string(101, 'x') + "\""));
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().toString(),
            "lot.json:31: level.task: must be 1 to 100 bytes without control characters");
}

TEST(SceneJsonMarkingErrors, UnknownTypeMissingPointAndDegenerate) {
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"arrow\"", "\"zebra\"")), 34,
                      "markings[1].type: expected \"line\" or \"arrow\", found \"zebra\""));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"to\": [0, 3]", "\"to\": [0, 0]")), 34,
                      "markings[1]: from and to must differ"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith(", \"to\": [0, 3]", "")), 34,
                      "markings[1]: missing \"to\""));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"width\": 0.12", "\"width\": 11")), 33,
                      "markings[0].width: must be finite, > 0 and at most 10 m"));
  EXPECT_TRUE(failsAt(parseSampleScene(goalWith("\"width\": 0.12", "\"paint\": 1")), 33,
                      "unknown key \"paint\" in markings[0]"));
}

}  // namespace
}  // namespace cardemo
