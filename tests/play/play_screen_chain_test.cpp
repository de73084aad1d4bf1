// Free drive in the play layer (what the window and the page both run): the bay chain beside the
// World on the free-drive lot, driven by key actions; each bay chimes, the time limit ends the
// run with its summary, best and recording, and that recording replays headless (as `cardemo
// replay --bay-chain`) to the same count.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/temp_dir.hpp"
#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "io/summary_json.hpp"
#include "play/play_screen.hpp"
#include "play_screen_driver.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;
using test::kStep;
using test::press;
using test::release;
using test::screenConfig;
using test::ScreenDriver;

nlohmann::json readSummary(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

// The free-drive lot with the car standing in its first free bay (A's west end, x = -40, y = 8),
// facing south: the second bay (B's west end) lies 16 m straight ahead.
Scene lotInFirstBay() {
  const Parsed<Scene> lot =
      loadScene(std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/parking-lot.json");
  EXPECT_TRUE(lot.ok()) << lot.error().toString();
  Scene scene = lot.value();
  scene.player.position = {-40.0, 8.0};
  scene.player.heading_deg = 270.0;
  return scene;
}

// Presses and releases the pedals through the screen's actions, one frame a step.
class PedalDriver {
 public:
  explicit PedalDriver(ScreenDriver& d) : d_(d) {}
  const World& world() const { return d_.screen().session().world(); }
  const BayChain& chain() const { return *d_.screen().chain().chain(); }
  // One frame holding `up` and `down`; true when it chimed.
  bool frame(bool up, bool down) {
    std::vector<PlayAction> actions;
    if (up != up_) actions.push_back(up ? press(DriveKey::kUp) : release(DriveKey::kUp));
    if (down != down_) actions.push_back(down ? press(DriveKey::kDown) : release(DriveKey::kDown));
    up_ = up;
    down_ = down;
    const bool chimed = d_.frame(std::move(actions), kStep).chime;
    chimes_ += chimed ? 1 : 0;
    return chimed;
  }
  // Stands (no pedal) until the count reaches `count`, at most `frames` frames.
  void standUntil(int count, int frames = 200) {
    for (int i = 0; i < frames && chain().count() < count; ++i) (void)frame(false, false);
  }
  // Drives straight ahead to stop with the car `target` m along `dir` from `start`: throttle while
  // the braking distance leaves room, then Down (which brakes and holds), let go once stopped.
  void driveTo(double target, const Eigen::Vector2d& start, const Eigen::Vector2d& dir) {
    bool braking = false;
    for (int i = 0; i < 2400; ++i) {
      const double at = (world().car().position - start).dot(dir);
      const double v = world().car().speed;
      if (braking && v == 0.0) break;
      braking = braking || at + v * v / (2.0 * 9.0) + v / 120.0 >= target;
      (void)frame(!braking, braking);
    }
    (void)frame(false, false);
  }
  int chimes() const { return chimes_; }

 private:
  ScreenDriver& d_;
  bool up_ = false;
  bool down_ = false;
  int chimes_ = 0;
};

TEST(PlayScreenChain, FreeDriveCountsBaysEndsAtTheLimitAndItsRecordingReplaysToTheSameCount) {
  const fs::path dir = testing::freshTempDir("screen_chain");
  const fs::path json = dir / "summary.json";
  const fs::path record = dir / "drive.replay";
  const fs::path best = dir / "best.json";
  const Scene scene = lotInFirstBay();
  PlayScreenConfig config = screenConfig(scene);
  config.json_path = json.string();
  config.session.record_path = record.string();
  config.best_scores_path = best.string();
  ScreenDriver d(std::move(config));
  PedalDriver drive(d);

  const PlayFrame& first = d.frame({}, kStep);
  ASSERT_NE(first.draw.goal, nullptr) << "free drive shows the chain's bay";
  ASSERT_EQ(first.draw.goal->chain, d.screen().chain().chain());
  EXPECT_EQ(drive.chain().bays().size(), 6u);
  EXPECT_EQ((first.draw.goal->challenge->goal().bay.center - Eigen::Vector2d(-40.0, 8.0)).norm(),
            0.0);

  drive.standUntil(1);
  EXPECT_EQ(drive.chain().count(), 1);
  EXPECT_EQ(drive.chimes(), 1) << "a bay parked chimes";
  drive.driveTo(16.0, {-40.0, 8.0}, {0.0, -1.0});
  drive.standUntil(2);
  ASSERT_EQ(drive.chain().count(), 2) << drive.world().car().position.transpose();
  EXPECT_EQ(drive.chimes(), 2);
  EXPECT_FALSE(d.ended());
  const PlayFrame& driving = d.frame({}, kStep);
  EXPECT_EQ(driving.draw.goal->challenge->goal().bay.center, drive.chain().bays()[2].bay.center);

  // Nothing more parked: the time limit (180 s on the chain's clock) ends the run.
  for (int i = 0; i < 4000 && !d.ended(); ++i) (void)d.frame({}, 1.0);
  ASSERT_TRUE(d.ended());
  ASSERT_TRUE(drive.chain().timedOut());
  const std::int64_t end_frame = d.worldFrame();
  (void)d.frame({}, 1.0);
  EXPECT_EQ(d.worldFrame(), end_frame) << "nothing is simulated once the chain is over";
  EXPECT_EQ(d.screen().takePublished(), std::vector<std::string>{record.string()});
  EXPECT_TRUE(d.screen().chain().newBest());

  const nlohmann::json summary = readSummary(json);
  ASSERT_TRUE(summary.is_object());
  const nlohmann::json& c = summary.at("bay_chain");
  EXPECT_EQ(c.at("count"), 2);
  EXPECT_EQ(c.at("bay"), "bay-3");
  EXPECT_EQ(c.at("bays"), 6);
  EXPECT_EQ(c.at("clock_frames"), 180 * 120);
  EXPECT_EQ(c.at("over"), true);
  EXPECT_EQ(c.at("best"), 2);
  EXPECT_EQ(c.at("new_best"), true);
  std::string warning;
  const BestScores saved = loadBestScores(best.string(), warning);
  ASSERT_NE(saved.findChain(scene.name), nullptr) << warning;
  EXPECT_EQ(saved.findChain(scene.name)->count, 2);

  // The recording, run headless with the chain beside it (`replay --bay-chain`): the same count,
  // bay and clock, and the same state hash.
  const Parsed<Replay> replay = loadReplay(record.string());
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  World world(scene, settingsForReplay(replay.value()));
  BayChain chain = startBayChain(world);
  runReplayInputs(world, replay.value(), [&chain](const World& w) { chain.observe(w); });
  const nlohmann::json headless = bayChainJson(chain);
  EXPECT_EQ(headless.at("count"), c.at("count"));
  EXPECT_EQ(headless.at("bay"), c.at("bay"));
  EXPECT_EQ(headless.at("clock_frames"), c.at("clock_frames"));
  EXPECT_EQ(headless.at("over"), true);
  EXPECT_EQ(hashHex(world.stateHash()), summary.at("hash"));

  // Enter retries: a fresh chain, with the best just saved shown.
  const PlayFrame& again = d.act(PlayActionKind::kConfirm, kStep);
  EXPECT_FALSE(d.ended());
  EXPECT_EQ(drive.chain().count(), 0);
  ASSERT_NE(again.draw.goal, nullptr);
  ASSERT_TRUE(again.draw.goal->chain_best.has_value());
  EXPECT_EQ(again.draw.goal->chain_best->count, 2);
  EXPECT_FALSE(again.draw.goal->new_best);
  fs::remove_all(dir);
}

TEST(PlayScreenChain, AWatchedFreeDriveSavesNoBestAndAPlainLotHasNoChain) {
  const fs::path dir = testing::freshTempDir("screen_chain_watch");
  const fs::path best = dir / "best.json";
  PlayScreenConfig config = screenConfig(lotInFirstBay());
  config.best_scores_path = best.string();
  // Stand for a second (the first bay parks), then drive off 4 m and stand till the limit.
  config.session.playback = {
      {120, InputFrame{}}, {120, InputFrame{true, false, false, false}}, {22000, InputFrame{}}};
  ScreenDriver d(std::move(config));
  for (int i = 0; i < 4000 && !d.ended(); ++i) (void)d.frame({}, 1.0);
  ASSERT_TRUE(d.ended());
  EXPECT_EQ(d.screen().chain().chain()->count(), 1);
  EXPECT_FALSE(d.screen().chain().newBest());
  EXPECT_FALSE(fs::exists(best)) << "a replay watched is no run of the player's";

  // A scene without free bays (the open floor) is plain free drive: no goal drawn, no end.
  ScreenDriver plain(screenConfig(test::openFloor(5.0)));
  EXPECT_EQ(plain.screen().chain().chain(), nullptr);
  EXPECT_EQ(plain.frame({}, kStep).draw.goal, nullptr);
  for (int i = 0; i < 3000; ++i) (void)plain.frame({}, 1.0);
  EXPECT_FALSE(plain.ended());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cardemo
