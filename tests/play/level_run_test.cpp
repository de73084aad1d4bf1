#include "play/level_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

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
