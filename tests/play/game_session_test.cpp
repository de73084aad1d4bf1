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

TEST(GameSession, RestartStartsAFreshWorldAndANumberedRecording) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "restart.replay").string();
  const std::string second = (dir / "restart-2.replay").string();
  const std::string third = (dir / "restart-3.replay").string();
  for (const std::string& p : {path, second, third}) fs::remove(p);
  GameSession session(lotConfig(path));
  EXPECT_EQ(session.attempt(), 1);
  EXPECT_EQ(session.recordPath(), path);
  for (int i = 0; i < 50; ++i) session.step({true, false, false, false});
  session.restart();
  EXPECT_EQ(session.world().frame(), 0);
  EXPECT_EQ(session.attempt(), 2);
  EXPECT_EQ(session.recordPath(), second);
  EXPECT_TRUE(session.recording());
  for (int i = 0; i < 7; ++i) session.step({});
  session.restart();
  for (int i = 0; i < 3; ++i) session.step({false, false, true, false});
  ASSERT_EQ(session.finishRecording(), "");
  // Each attempt kept its own file, with its own frames.
  const std::pair<std::string, std::int64_t> expected[] = {{path, 50}, {second, 7}, {third, 3}};
  for (const auto& [file, frames] : expected) {
    const Parsed<Replay> replay = loadReplay(file);
    ASSERT_TRUE(replay.ok()) << file;
    EXPECT_EQ(replay.value().totalFrames(), frames) << file;
  }
  EXPECT_TRUE(loadReplay(path).value().runs.at(0).keys.up);
  EXPECT_TRUE(loadReplay(third).value().runs.at(0).keys.left);
}

// Levels played one after another from the picker continue the attempt count: the next level's
// first attempt records beside, not over, the previous level's.
TEST(GameSession, FirstAttemptContinuesTheCountOfEarlierGames) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "chain.replay").string();
  const std::string third = (dir / "chain-3.replay").string();
  const std::string fourth = (dir / "chain-4.replay").string();
  for (const std::string& p : {path, third, fourth}) fs::remove(p);
  SessionConfig config = lotConfig(path);
  config.first_attempt = 3;
  GameSession session(std::move(config));
  EXPECT_EQ(session.attempt(), 3);
  EXPECT_EQ(session.recordPath(), third);
  // The player counts the attempts at this scene from 1, whatever the earlier games counted.
  EXPECT_EQ(session.sceneAttempt(), 1);
  for (int i = 0; i < 4; ++i) session.step({true, false, false, false});
  session.restart();
  EXPECT_EQ(session.attempt(), 4);
  EXPECT_EQ(session.sceneAttempt(), 2);
  EXPECT_EQ(session.recordPath(), fourth);
  for (int i = 0; i < 2; ++i) session.step({});
  ASSERT_EQ(session.finishRecording(), "");
  EXPECT_FALSE(fs::exists(path));
  ASSERT_TRUE(loadReplay(third).ok());
  EXPECT_EQ(loadReplay(third).value().totalFrames(), 4);
  ASSERT_TRUE(loadReplay(fourth).ok());
  EXPECT_EQ(loadReplay(fourth).value().totalFrames(), 2);
}

TEST(GameSession, RestartAfterGameOverKeepsTheEndedRun) {
  const fs::path dir = fs::temp_directory_path() / "cardemo_session_test";
  fs::create_directories(dir);
  const std::string path = (dir / "ended.replay").string();
  const std::string second = (dir / "ended-2.replay").string();
  fs::remove(path);
  fs::remove(second);
  SessionConfig config = lotConfig(path);
  config.scene.player.health = 1;
  GameSession session(std::move(config));
  for (int i = 0; i < 3000 && !session.world().gameOver(); ++i) session.step({true});
  ASSERT_TRUE(session.world().gameOver());
  const std::uint64_t ended_hash = session.world().stateHash();
  const std::int64_t ended_frames = session.world().frame();
  session.restart();
  for (int i = 0; i < 10; ++i) session.step({});
  ASSERT_EQ(session.finishRecording(), "");
  const Parsed<Replay> replay = loadReplay(path);
  ASSERT_TRUE(replay.ok());
  Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  ASSERT_TRUE(scene.ok());
  Scene s = std::move(scene).value();
  s.player.health = 1;
  World world(std::move(s), settingsForReplay(replay.value()));
  runReplayInputs(world, replay.value());
  EXPECT_EQ(world.frame(), ended_frames);
  EXPECT_EQ(world.stateHash(), ended_hash);
  EXPECT_TRUE(fs::exists(second));
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
  EXPECT_TRUE(session.ended());
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
