// GameSession: playback then live input on one path, recording, restart, game over, blending.

#include "play/game_session.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

const std::string kLot = std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/parking-lot.json";

SessionConfig lotConfig(const std::string& record_path = {}) {
  Parsed<Scene> scene = loadScene(kLot);
  EXPECT_TRUE(scene.ok());
  SessionConfig config;
  config.scene = std::move(scene).value();
  config.scene_path = kLot;
  config.record_path = record_path;
  return config;
}

TEST(GameSession, PlaysBackThenTakesLiveInput) {
  SessionConfig config = lotConfig();
  config.playback = {{3, {true, false, false, false}}, {2, {false, false, true, false}}};
  GameSession session(std::move(config));
  const InputFrame live{false, true, false, false};
  EXPECT_TRUE(session.playingBack());
  EXPECT_EQ(session.playbackLeft(), 5);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(session.step(live).up);
  for (int i = 0; i < 2; ++i) EXPECT_TRUE(session.step(live).left);
  EXPECT_FALSE(session.playingBack());
  EXPECT_TRUE(session.step(live).down);
  EXPECT_EQ(session.world().frame(), 6);
}

TEST(GameSession, RecordingReplaysToTheSameState) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "drive.replay").string();
  fs::remove(path);
  GameSession session(lotConfig(path));
  for (int i = 0; i < 900; ++i) session.step({true, false, i > 400 && i < 500, false});
  ASSERT_EQ(session.finishRecording(), "");
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  ASSERT_TRUE(scene.ok()) << scene.error().toString();
  World world(std::move(scene).value(), settingsForReplay(replay.value()));
  runReplayInputs(world, replay.value());
  EXPECT_EQ(world.frame(), session.world().frame());
  EXPECT_EQ(world.stateHash(), session.world().stateHash());
  EXPECT_EQ(world.hits().size(), session.world().hits().size());
}

TEST(GameSession, RestartStartsAFreshWorldAndRecording) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "restart.replay").string();
  GameSession session(lotConfig(path));
  for (int i = 0; i < 50; ++i) session.step({true, false, false, false});
  session.restart();
  EXPECT_EQ(session.world().frame(), 0);
  EXPECT_TRUE(session.recording());
  for (int i = 0; i < 7; ++i) session.step({});
  ASSERT_EQ(session.finishRecording(), "");
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok());
  EXPECT_EQ(replay.value().totalFrames(), 7);
}

TEST(GameSession, GameOverFreezesAndFinishesTheRecording) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "over.replay").string();
  fs::remove(path);
  SessionConfig config = lotConfig(path);
  config.scene.player.health = 1;  // the first hit ends the game
  GameSession session(std::move(config));
  for (int i = 0; i < 3000 && !session.world().gameOver(); ++i) session.step({true});
  ASSERT_TRUE(session.world().gameOver());
  EXPECT_FALSE(session.recording());
  EXPECT_TRUE(fs::exists(path));
  const std::int64_t frame = session.world().frame();
  session.step({true});
  EXPECT_EQ(session.world().frame(), frame);
}

TEST(BlendBoxes, InterpolatesCentreAndHeading) {
  const Obb2 a = Obb2::fromDegrees({0, 0}, 0, 4, 2);
  const Obb2 b = Obb2::fromDegrees({2, 4}, 90, 4, 2);
  const Obb2 mid = blendBoxes(a, b, 0.5);
  EXPECT_NEAR(mid.center.x(), 1.0, 1e-12);
  EXPECT_NEAR(mid.center.y(), 2.0, 1e-12);
  EXPECT_NEAR(mid.axis.norm(), 1.0, 1e-12);
  EXPECT_NEAR(mid.axis.x(), mid.axis.y(), 1e-12);
  EXPECT_EQ(blendBoxes(a, b, 1.0).center, b.center);
  EXPECT_EQ(blendBoxes(a, b, 0.0).center, a.center);
}

}  // namespace
}  // namespace cardemo
