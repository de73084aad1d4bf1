#include "play/level_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "../sim/scene_builders.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

// The car starts at rest in the bay (with no hold time it parks at frame 0); tests move the bay
// and give the car a speed so that it rolls in and brakes.
Scene rollIn() {
  Scene s = test::sceneWith({});
  s.name = "roll-in";
  Goal g;
  g.bay.center = {0.0, 0.0};
  g.hold_time = 0.0;
  s.goal = g;
  return s;
}

TEST(LevelRun, ParkedScoreIsSavedAndKeptOnlyWhenBetter) {
  const fs::path dir = fs::temp_directory_path() / ("cardemo_levelrun_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string path = (dir / "best.json").string();
  World world(rollIn());
  LevelRun run(world, path);
  ASSERT_NE(run.challenge(), nullptr);
  EXPECT_TRUE(run.over());  // parked at frame 0, and saved at once
  EXPECT_FALSE(run.best().has_value());
  EXPECT_TRUE(run.newBest());
  ASSERT_TRUE(fs::exists(path));
  fs::remove(path);

  Scene moving = rollIn();
  moving.goal->bay.center = {0.5, 0.0};
  moving.player.speed = 1.0;
  World w2(moving);
  LevelRun run2(w2, path);
  EXPECT_FALSE(run2.over());
  bool ended = false;
  for (int i = 0; i < 600 && !ended; ++i) {
    w2.step(InputFrame{false, true, false, false});
    ended = run2.observe(w2);
  }
  ASSERT_TRUE(ended);
  ASSERT_TRUE(run2.challenge()->parkedFrame().has_value());
  EXPECT_TRUE(run2.newBest());
  EXPECT_EQ(run2.takeWarning(), "");
  std::string warning;
  const BestScores saved = loadBestScores(path, warning);
  ASSERT_NE(saved.find("roll-in"), nullptr);
  EXPECT_EQ(saved.find("roll-in")->frames, *run2.challenge()->parkedFrame());

  // The same run again is not better: nothing new; the restart shows the stored best.
  World w3(moving);
  LevelRun run3(w3, path);
  ASSERT_TRUE(run3.best().has_value());
  EXPECT_EQ(run3.best()->frames, *run2.challenge()->parkedFrame());
  for (int i = 0; i < 600 && !run3.over(); ++i) {
    w3.step(InputFrame{false, true, false, false});
    (void)run3.observe(w3);
  }
  EXPECT_FALSE(run3.newBest());
  fs::remove_all(dir);
}

// A replay being watched parks the car, shows the stored best, and neither saves nor beats it.
TEST(LevelRun, AReplayBeingWatchedNeverSetsABest) {
  const fs::path dir =
      fs::temp_directory_path() / ("cardemo_levelrun_r_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string path = (dir / "best.json").string();
  World world(rollIn());
  LevelRun watched(world, path, /*keeps_best=*/false);
  ASSERT_NE(watched.challenge(), nullptr);
  EXPECT_TRUE(watched.over());  // parked at frame 0, as a played run would
  EXPECT_FALSE(watched.newBest());
  EXPECT_FALSE(fs::exists(path));

  // A stored best (worse than this run) is shown and stays as it was.
  BestScores stored;
  ParkingScore slow;
  slow.frames = 5000;
  slow.seconds = 5000.0 / 120.0;
  slow.damage = 40;
  slow.stars = 1;
  ASSERT_TRUE(stored.offer("roll-in", slow));
  ASSERT_EQ(saveBestScores(path, stored), "");
  const std::string before = bestScoresText(stored);
  LevelRun again(world, path, false);
  ASSERT_TRUE(again.best().has_value());
  EXPECT_EQ(again.best()->frames, 5000);
  EXPECT_FALSE(again.newBest());
  again.restart(world);
  EXPECT_FALSE(again.newBest());
  std::ifstream in(path);
  const std::string after{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(after, before);
  // The same run played (the default) is a new best.
  LevelRun played(world, path);
  EXPECT_TRUE(played.newBest());
  fs::remove_all(dir);
}

TEST(LevelRun, EndsOnlyOnceTheHoldIsOver) {
  Scene scene = rollIn();
  scene.goal->hold_time = 0.25;  // 30 frames at 120 Hz
  World world(scene);
  LevelRun run(world, "");
  EXPECT_FALSE(run.over());
  int ended_at = -1;
  for (int i = 1; i <= 40 && ended_at < 0; ++i) {
    world.step(InputFrame{});
    if (run.observe(world)) ended_at = i;
  }
  EXPECT_EQ(ended_at, 30);
  EXPECT_TRUE(run.over());
  EXPECT_EQ(run.challenge()->parkedFrame(), 30);
}

TEST(LevelRun, CorruptBestFileWarnsOnceAndTheRunGoesOn) {
  const fs::path dir =
      fs::temp_directory_path() / ("cardemo_levelrun_c_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "best.json") << "{{{";
  World world(rollIn());
  LevelRun run(world, (dir / "best.json").string());
  const std::string warning = run.takeWarning();
  EXPECT_NE(warning.find("best scores ignored"), std::string::npos) << warning;
  EXPECT_EQ(run.takeWarning(), "");
  EXPECT_NE(run.challenge(), nullptr);
  fs::remove_all(dir);
}

TEST(LevelRun, FreeDriveHasNoChallenge) {
  World world(test::sceneWith({}));
  LevelRun run(world, "");
  EXPECT_EQ(run.challenge(), nullptr);
  EXPECT_FALSE(run.over());
  world.step(InputFrame{true, false, false, false});
  EXPECT_FALSE(run.observe(world));
}

}  // namespace
}  // namespace cardemo
