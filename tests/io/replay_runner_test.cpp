// loadReplayScene and friends: a scene that cannot be read is reported where it was named.

#include "io/replay_runner.hpp"

#include <gtest/gtest.h>

#include <string>

#include "../support/cli_run.hpp"
#include "io/replay_text.hpp"

namespace cardemo {
namespace {

const std::string kNoFile = ": cannot open: No such file or directory";

// A replay file in the scratch folder whose line 2 names `scene`.
std::string replayNaming(const std::string& scene) {
  return test::writeScratch("drive.replay", "cardemo-replay 1\nscene " + scene + "\n10 U\n")
      .string();
}

TEST(ReplayScene, MissingSceneIsReportedOnTheReplaysSceneLine) {
  const std::string path = replayNaming("../scenes/nope.json");
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  EXPECT_EQ(replay.value().scene_line, 2);
  const Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().toString(), path + ":2: scene ../scenes/nope.json" + kNoFile);
}

TEST(ReplayScene, MissingOverrideNamesTheOption) {
  const std::string path = replayNaming(test::assetPath("scenes/parking-lot.json"));
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  const Parsed<Scene> scene = loadReplayScene(replay.value(), path, "/nonexistent/x.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().toString(), "--scene /nonexistent/x.json" + kNoFile);
}

TEST(ReplayScene, ErrorsInsideTheSceneKeepTheScenesLine) {
  const auto bad =
      test::writeScratch("bad.json", "{\n  \"format\": \"cardemo-scene/1\",\n  oops\n}\n");
  const std::string path = replayNaming("bad.json");
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  const Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().file, bad.string());
  EXPECT_EQ(scene.error().line, 3);
}

TEST(ReplayScene, ReadableSceneLoads) {
  const std::string path = replayNaming(test::assetPath("scenes/parking-lot.json"));
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  EXPECT_TRUE(loadSceneOfReplay(replay.value(), path).ok());
  EXPECT_TRUE(loadSceneOption("--scene", test::assetPath("scenes/parking-lot.json")).ok());
}

}  // namespace
}  // namespace cardemo
