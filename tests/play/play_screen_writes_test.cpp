// PlayScreen's writes: each attempt's recording is published when the attempt ends, the summary
// JSON is written when a run ends and when the level is left, and failures are said once.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/temp_dir.hpp"
#include "io/replay_text.hpp"
#include "play/play_screen.hpp"
#include "play_screen_driver.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;
using test::kStep;
using test::press;
using test::screenConfig;
using test::ScreenDriver;
using K = PlayActionKind;

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

std::int64_t replayFrames(const fs::path& path) {
  const Parsed<Replay> replay = loadReplay(path.string());
  EXPECT_TRUE(replay.ok()) << replay.error().toString();
  return replay.ok() ? replay.value().totalFrames() : -1;
}

TEST(PlayScreenWrites, RestartPublishesThePreviousAttemptsRecording) {
  const fs::path dir = testing::freshTempDir("screen_restart");
  const fs::path first = dir / "drive.replay";
  PlayScreenConfig config = screenConfig(test::openFloor());
  config.session.record_path = first.string();
  ScreenDriver d(std::move(config));
  ASSERT_TRUE(d.screen().ready());
  const PlayFrame& driving = d.frame({press(DriveKey::kUp)}, 5 * kStep);
  EXPECT_EQ(driving.draw.status, "recording to " + first.string());
  EXPECT_FALSE(fs::exists(first));

  const PlayFrame& restarted = d.act(K::kRestart, 2 * kStep);
  ASSERT_TRUE(fs::exists(first));
  EXPECT_FALSE(fs::exists(first.string() + ".part"));
  EXPECT_EQ(replayFrames(first), 5);
  EXPECT_EQ(d.screen().takePublished(), std::vector<std::string>{first.string()});
  const fs::path second = dir / "drive-2.replay";
  EXPECT_EQ(restarted.draw.status, "attempt 2  recording to " + second.string());
  EXPECT_TRUE(fs::exists(second.string() + ".part"));

  const GameOutcome outcome = d.screen().finish();
  EXPECT_EQ(outcome.status, 0);
  EXPECT_EQ(outcome.last_attempt, 2);
  EXPECT_EQ(replayFrames(second), 2);
  EXPECT_EQ(d.screen().takePublished(), std::vector<std::string>{second.string()});
  EXPECT_TRUE(d.screen().takeMessages().empty());
}

TEST(PlayScreenWrites, GameOverWritesTheSummaryAndPublishesAtOnce) {
  const fs::path dir = testing::freshTempDir("screen_over");
  const fs::path json = dir / "summary.json";
  const fs::path record = dir / "crash.replay";
  PlayScreenConfig config = screenConfig(test::crashScene());
  config.json_path = json.string();
  config.session.record_path = record.string();
  ScreenDriver d(std::move(config));
  d.runToEnd();
  ASSERT_TRUE(d.screen().session().world().gameOver());
  // Written by the frame that ended the game, before anything leaves the level.
  ASSERT_TRUE(fs::exists(json));
  const nlohmann::json summary = readJson(json);
  EXPECT_EQ(summary.value("game_over", false), true);
  EXPECT_EQ(summary.value("frames", -1), d.worldFrame());
  EXPECT_EQ(replayFrames(record), d.worldFrame());
  EXPECT_EQ(d.screen().takePublished(), std::vector<std::string>{record.string()});
  EXPECT_EQ(d.frame({}, 1.0).draw.status, "recorded to " + record.string());

  // Retry: the next attempt's summary replaces it when the level is left.
  fs::remove(json);
  (void)d.act(K::kConfirm, 3 * kStep);
  EXPECT_FALSE(fs::exists(json));
  EXPECT_EQ(d.screen().finish().status, 0);
  EXPECT_EQ(readJson(json).value("frames", -1), 3);
}

TEST(PlayScreenWrites, ParkingEndsTheRunWithSummaryChimeAndRecording) {
  const fs::path dir = testing::freshTempDir("screen_parked");
  const fs::path json = dir / "summary.json";
  const fs::path record = dir / "park.replay";
  PlayScreenConfig config = screenConfig(test::rollInLevel());
  config.json_path = json.string();
  config.session.record_path = record.string();
  config.links = {true, true};
  ScreenDriver d(std::move(config));
  (void)d.frame({press(DriveKey::kDown)});
  bool chimed = false;
  for (int i = 0; i < 2000 && !d.ended(); ++i) chimed = d.frame({}, kStep).chime;
  ASSERT_TRUE(d.screen().level().over());
  const std::optional<std::int64_t> parked = d.screen().level().challenge()->parkedFrame();
  ASSERT_TRUE(parked.has_value());
  EXPECT_TRUE(chimed);  // in the frame that parked, and only then
  const PlayFrame& after = d.frame({}, 1.0);
  EXPECT_FALSE(after.chime);
  EXPECT_EQ(after.steps, 0);  // nothing more is simulated
  EXPECT_TRUE(after.draw.run_over);
  EXPECT_EQ(after.draw.goal->keys, "Enter retry    N next level    Esc levels");
  ASSERT_TRUE(fs::exists(json));
  EXPECT_EQ(readJson(json).value("parked", nlohmann::json()), *parked);
  EXPECT_EQ(replayFrames(record), *parked);
  EXPECT_EQ(d.screen().takePublished(), std::vector<std::string>{record.string()});
}

TEST(PlayScreenWrites, TimeUpEndsTheRunWithASummaryButNoChime) {
  const fs::path dir = testing::freshTempDir("screen_timeup");
  const fs::path json = dir / "summary.json";
  Scene scene = test::rollInLevel();
  scene.player.speed = 0.0;
  scene.goal->bay.center = {5.0, 0.0};  // never reached
  scene.goal->time_limit = 0.1;
  PlayScreenConfig config = screenConfig(std::move(scene));
  config.json_path = json.string();
  ScreenDriver d(std::move(config));
  // The clock starts when the car first moves: drive off.
  bool chimed = d.frame({press(DriveKey::kUp)}, kStep).chime;
  for (int i = 0; i < 100 && !d.ended(); ++i) chimed = chimed || d.frame({}, kStep).chime;
  ASSERT_TRUE(d.screen().level().challenge()->timedOut());
  EXPECT_FALSE(chimed);
  ASSERT_TRUE(fs::exists(json));
  EXPECT_TRUE(readJson(json).at("parked").is_null());
  EXPECT_EQ(d.frame({}, kStep).draw.goal->keys, "Enter retry    Esc quit");
}

TEST(PlayScreenWrites, AReplayWatchedToParkedSetsNoBestScore) {
  const fs::path dir = testing::freshTempDir("screen_best");
  const fs::path best = dir / "best.json";
  for (const bool watched : {false, true}) {
    fs::remove(best);
    PlayScreenConfig config = screenConfig(test::rollInLevel());
    config.best_scores_path = best.string();
    if (watched) config.session.playback = {{2000, InputFrame{false, true, false, false}}};
    ScreenDriver d(std::move(config));
    (void)d.frame({press(DriveKey::kDown)});
    d.runToEnd();
    ASSERT_TRUE(d.screen().level().challenge()->parkedFrame().has_value());
    EXPECT_EQ(fs::exists(best), !watched);
  }
}

TEST(PlayScreenWrites, ARecordingThatCannotStartStopsTheLevel) {
  const fs::path dir = testing::freshTempDir("screen_nostart");
  const fs::path record = dir / "drive.replay";
  std::ofstream(record.string() + ".part")
      << "cardemo-replay 1\n";  // another game's, or a leftover
  PlayScreenConfig config = screenConfig(test::openFloor());
  config.session.record_path = record.string();
  PlayScreen screen(std::move(config));
  EXPECT_FALSE(screen.ready());
  EXPECT_EQ(screen.outcome().status, 2);
  const std::vector<std::string> messages = screen.takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find(record.string()), std::string::npos) << messages[0];
}

TEST(PlayScreenWrites, ASummaryThatCannotBeWrittenIsSaidAndExitsTwo) {
  const fs::path dir = testing::freshTempDir("screen_badjson");
  PlayScreenConfig config = screenConfig(test::crashScene());
  config.json_path = (dir / "no-such-folder" / "summary.json").string();
  ScreenDriver d(std::move(config));
  d.runToEnd();
  const std::vector<std::string> said = d.screen().takeMessages();
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("summary.json"), std::string::npos) << said[0];
  const GameOutcome outcome = d.screen().finish();
  EXPECT_EQ(outcome.status, 2);
  EXPECT_EQ(d.screen().takeMessages().size(), 1u);  // finish() tries once more
}

}  // namespace
}  // namespace cardemo
