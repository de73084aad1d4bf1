// ChainRun: free drive's bay chain beside the World, only on a scene without a goal that has free
// bays, and its best count kept in the best-scores file when the chain ends.

#include "play/chain_run.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "../sim/scene_builders.hpp"
#include "../support/temp_dir.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;
using test::parkedCar;
using test::sceneWith;

// A row of cars facing north at x = 0, 5 and 15: free bays at x = -5, 10 and 20. The car starts
// in the bay at x = 10, facing north, so standing still parks it; a car across the lane 12 m
// ahead is what a wreck drives into.
Scene rowLot(int health = 100) {
  Scene s = sceneWith({parkedCar("a", 0, 0, 90), parkedCar("b", 5, 0, 90),
                       parkedCar("c", 15, 0, 90), parkedCar("across", 10, 14, 0)},
                      10.0, 0.0, 90.0);
  s.name = "row-lot";
  s.player.health = health;
  return s;
}

InputFrame keys(bool up, bool down) {
  InputFrame in;
  in.up = up;
  in.down = down;
  return in;
}

// Stands for `frames` steps, then drives forward for `drive` steps, brakes to a stop and stands
// until the chain is over (its clock started with the move), at most `limit` steps. Returns true
// when it ended on a step.
bool standThenRunOut(World& world, ChainRun& run, int frames, int drive = 10, int limit = 30000) {
  bool ended = false;
  for (int i = 0; i < limit && !run.over(); ++i) {
    const bool up = i >= frames && i < frames + drive;
    const bool down = i >= frames + drive && i < frames + drive + 200;
    world.step(keys(up, down));
    ended = run.observe(world) || ended;
  }
  return ended;
}

TEST(ChainRun, OnlyAGoallessSceneWithFreeBaysHasAChain) {
  const World open(sceneWith({}));
  EXPECT_EQ(ChainRun(open, "").chain(), nullptr);
  EXPECT_FALSE(ChainRun(open, "").over()) << "plain free drive never ends by itself";
  Scene level = rowLot();
  level.goal = Goal{};
  EXPECT_EQ(ChainRun(World(level), "").chain(), nullptr);
  const ChainRun lot(World(rowLot()), "");
  ASSERT_NE(lot.chain(), nullptr);
  EXPECT_EQ(lot.chain()->bays().size(), 3u);
  EXPECT_EQ(lot.chain()->count(), 0);
}

TEST(ChainRun, TheCountIsSavedWhenTheChainEndsAndKeptOnlyWhenBetter) {
  const fs::path dir = testing::freshTempDir("chainrun_best");
  const std::string path = (dir / "best.json").string();
  World world(rowLot());
  ChainRun run(world, path);
  EXPECT_FALSE(run.best().has_value());
  EXPECT_TRUE(standThenRunOut(world, run, 100));
  ASSERT_TRUE(run.chain()->timedOut());
  EXPECT_EQ(run.chain()->count(), 1);
  EXPECT_TRUE(run.newBest());
  EXPECT_EQ(run.takeWarning(), "");
  std::string warning;
  const BestScores saved = loadBestScores(path, warning);
  ASSERT_NE(saved.findChain("row-lot"), nullptr);
  EXPECT_EQ(saved.findChain("row-lot")->count, 1);
  EXPECT_EQ(saved.find("row-lot"), nullptr) << "no level score";

  // The same again is no better: the stored best is shown and kept.
  World again(rowLot());
  ChainRun second(again, path);
  ASSERT_TRUE(second.best().has_value());
  EXPECT_EQ(second.best()->count, 1);
  EXPECT_TRUE(standThenRunOut(again, second, 100));
  EXPECT_FALSE(second.newBest());
  // A restart keeps the best and starts a fresh chain.
  World fresh(rowLot());
  second.restart(fresh);
  EXPECT_EQ(second.chain()->count(), 0);
  EXPECT_FALSE(second.over());
  EXPECT_EQ(second.best()->count, 1);
  fs::remove_all(dir);
}

TEST(ChainRun, AWreckEndsTheChainWithItsCount) {
  const fs::path dir = testing::freshTempDir("chainrun_wreck");
  const std::string path = (dir / "best.json").string();
  World world(rowLot(5));
  ChainRun run(world, path);
  bool ended = false;
  for (int i = 0; i < 600 && !ended; ++i) {
    world.step(keys(i >= 70, false));  // parked in the first 61 steps, then into `across`
    ended = run.observe(world);
  }
  ASSERT_TRUE(ended);
  EXPECT_TRUE(world.gameOver());
  EXPECT_TRUE(run.chain()->wrecked());
  EXPECT_EQ(run.chain()->count(), 1);
  EXPECT_TRUE(run.newBest());
  std::string warning;
  EXPECT_EQ(loadBestScores(path, warning).findChain("row-lot")->count, 1);
  fs::remove_all(dir);
}

TEST(ChainRun, NoBayParkedOrAWatchedReplaySavesNothing) {
  const fs::path dir = testing::freshTempDir("chainrun_none");
  const std::string path = (dir / "best.json").string();
  {
    // Drives off at once, 4 m out of the bay: no bay parked when the time runs out.
    World world(rowLot());
    ChainRun run(world, path);
    EXPECT_TRUE(standThenRunOut(world, run, 0, 150));
    EXPECT_EQ(run.chain()->count(), 0);
    EXPECT_FALSE(run.newBest());
    EXPECT_FALSE(fs::exists(path));
  }
  {
    World world(rowLot());
    ChainRun run(world, path, /*keeps_best=*/false);
    EXPECT_TRUE(standThenRunOut(world, run, 100));
    EXPECT_EQ(run.chain()->count(), 1);
    EXPECT_FALSE(run.newBest());
    EXPECT_FALSE(fs::exists(path));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cardemo
