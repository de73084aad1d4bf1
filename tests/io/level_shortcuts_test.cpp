// Each level's obvious shortcut does not park: the checks beside the golden replays
// (assets/replays/level-*.replay), which show that the intended manoeuvre does.

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "io/replay_text.hpp"
#include "io/scene_json.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo::level_shortcuts_test {
namespace {

// One leg of a drive: keys held for `frames` steps, or (frames 0) until the car stands still.
struct Leg {
  std::string_view keys;
  int frames = 0;
};

InputFrame inputOf(std::string_view keys) {
  InputFrame in;
  for (const char c : keys) {
    in.up = in.up || c == 'U';
    in.down = in.down || c == 'D';
    in.left = in.left || c == 'L';
    in.right = in.right || c == 'R';
  }
  return in;
}

Scene level(std::string_view file) {
  const Parsed<Scene> scene = loadScene(std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/levels/" +
                                        std::string(file) + ".json");
  EXPECT_TRUE(scene.ok()) << scene.error().toString();
  return scene.ok() ? scene.value() : Scene{};
}

// Drives `legs`, then lets the car stand for 4 s; true when the challenge parked the car.
bool parks(const Scene& scene, const std::vector<Leg>& legs) {
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  challenge.observe(world);
  const auto step = [&](const InputFrame& in) {
    world.step(in);
    challenge.observe(world);
  };
  for (const Leg& leg : legs) {
    const InputFrame in = inputOf(leg.keys);
    if (leg.frames > 0) {
      for (int i = 0; i < leg.frames && !challenge.over(); ++i) step(in);
    } else {
      // Brake to a stop (at most 10 s), then let go of the pedal.
      for (int i = 0; i < 1200 && !challenge.over() && world.car().speed != 0.0; ++i) step(in);
    }
  }
  for (int i = 0; i < 480 && !challenge.over(); ++i) step(InputFrame{});
  return challenge.parkedFrame().has_value();
}

// Full throttle straight ahead for `frames`, then brake to a stop.
std::vector<Leg> straight(int frames) {
  return {{"U", frames}, {"D", 0}};
}

TEST(LevelShortcuts, SlalomStraightDrivesNeverPark) {
  const Scene slalom = level("level-5-slalom");
  ASSERT_TRUE(slalom.goal.has_value());
  ASSERT_EQ(slalom.goal->gates.size(), 3u);
  Scene open = slalom;
  open.goal->gates.clear();
  int parked_without_gates = 0;
  for (int frames = 30; frames <= 1500; frames += 6) {
    EXPECT_FALSE(parks(slalom, straight(frames))) << "throttle for " << frames << " frames";
    parked_without_gates += parks(open, straight(frames)) ? 1 : 0;
  }
  // Without its gates the level falls to the shortcut: the test is not vacuous.
  EXPECT_GT(parked_without_gates, 0);
}

TEST(LevelShortcuts, StraightInRammingTheWallNeverParks) {
  // Level 1: use the back wall as the brake (full throttle, never brake).
  const Scene s = level("level-1-straight");
  for (int frames = 200; frames <= 1200; frames += 25) {
    EXPECT_FALSE(parks(s, {{"U", frames}})) << frames;
  }
}

TEST(LevelShortcuts, ReverseBayNoseFirstNeverParks) {
  // Level 2: drive forwards into the bay (the car must end facing out).
  const Scene s = level("level-2-reverse");
  for (int run : {20, 40, 60, 80, 100, 120}) {
    for (int turn = 60; turn <= 300; turn += 20) {
      for (int in : {0, 40, 80, 120}) {
        EXPECT_FALSE(parks(s, {{"U", run}, {"UL", turn}, {"U", in}, {"D", 0}}))
            << run << " " << turn << " " << in;
      }
    }
  }
}

TEST(LevelShortcuts, ParallelNoseFirstNeverParks) {
  // Level 3: steer forwards into the gap instead of reversing in.
  const Scene s = level("level-3-parallel");
  for (int run = 0; run <= 200; run += 25) {
    for (int out = 20; out <= 140; out += 20) {
      for (int back = 20; back <= 140; back += 20) {
        EXPECT_FALSE(parks(s, {{"U", run}, {"UR", out}, {"UL", back}, {"D", 0}}))
            << run << " " << out << " " << back;
      }
    }
  }
}

TEST(LevelShortcuts, GarageRammingTheBackWallNeverParks) {
  // Level 4: turn in and let the garage's back wall stop the car.
  const Scene s = level("level-4-garage");
  for (int run = 40; run <= 140; run += 10) {
    for (int turn = 100; turn <= 260; turn += 20) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UL", turn}, {"U", 600}})) << run << " " << turn;
    }
  }
}

TEST(LevelShortcuts, ThreePointTurnInOneSweepNeverParks) {
  // Level 6: turn round in one forward sweep on full lock (or one reverse sweep).
  const Scene s = level("level-6-turn");
  for (int run = 0; run <= 120; run += 20) {
    for (int sweep = 60; sweep <= 900; sweep += 40) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UL", sweep}, {"D", 0}})) << run << " " << sweep;
      EXPECT_FALSE(parks(s, {{"U", run}, {"UR", sweep}, {"D", 0}})) << run << " " << sweep;
      EXPECT_FALSE(parks(s, {{"U", run}, {"D", 0}, {"DL", sweep}, {"U", 0}}))
          << run << " " << sweep;
    }
  }
}

TEST(LevelShortcuts, AlleyStraightOnOrTurningEarlyNeverParks) {
  // Level 7: straight on past the alley's end, or turning towards the bay before leaving it.
  const Scene s = level("level-7-alley");
  for (int frames = 60; frames <= 1200; frames += 20) {
    EXPECT_FALSE(parks(s, straight(frames))) << frames;
  }
  for (int run = 100; run <= 500; run += 25) {
    for (int turn = 60; turn <= 240; turn += 30) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UR", turn}, {"U", 60}, {"D", 0}})) << run << " " << turn;
    }
  }
}

TEST(LevelShortcuts, AngledBayStraightOrSquareNeverParks) {
  // Level 8: stop beside the bay without turning in, or swing in square (90 degrees) to it.
  const Scene s = level("level-8-angled");
  for (int frames = 20; frames <= 600; frames += 10) {
    EXPECT_FALSE(parks(s, straight(frames))) << frames;
  }
  for (int run = 0; run <= 120; run += 10) {
    // Full right lock until the car faces the back wall (-90 degrees) or beyond.
    for (int turn = 300; turn <= 600; turn += 50) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UR", turn}, {"D", 0}})) << run << " " << turn;
    }
  }
}

TEST(LevelShortcuts, ConesUTurnShortOfTheirEndNeverParks) {
  // Level 9: turn round before the end of the cone line (the golden drive runs 391 frames first),
  // or stop beside the bay on the wrong side of the cones.
  const Scene s = level("level-9-cones");
  for (int run = 40; run <= 300; run += 20) {
    for (int back = 60; back <= 420; back += 60) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UL", 300}, {"U", back}, {"D", 0}}))
          << run << " " << back;
    }
  }
  for (int frames = 20; frames <= 400; frames += 20) {
    EXPECT_FALSE(parks(s, straight(frames))) << frames;
  }
}

// The challenge after running `runs` on `scene` (then 4 s standing), stopped when it is over.
ParkingChallenge runChallenge(const Scene& scene, const std::vector<InputRun>& runs) {
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  challenge.observe(world);
  for (const InputRun& run : runs) {
    for (std::int64_t i = 0; i < run.count && !challenge.over(); ++i) {
      world.step(run.keys);
      challenge.observe(world);
    }
  }
  for (int i = 0; i < 480 && !challenge.over(); ++i) {
    world.step(InputFrame{});
    challenge.observe(world);
  }
  return challenge;
}

// Level 10's golden inputs with the standing run that parks bay 1 made `frames` long.
std::vector<InputRun> chainWithWaitInBay1(const Scene& scene, const std::vector<InputRun>& golden,
                                          std::int64_t frames) {
  const ParkingChallenge parked = runChallenge(scene, golden);
  EXPECT_TRUE(parked.bayParkedFrame(0).has_value());
  const std::int64_t at = parked.bayParkedFrame(0).value_or(0);
  std::vector<InputRun> runs = golden;
  std::int64_t start = 0;
  for (InputRun& run : runs) {
    if (start < at && at <= start + run.count) {
      EXPECT_EQ(run.keys, InputFrame{}) << "bay 1 is parked while standing";
      run.count = frames;
      return runs;
    }
    start += run.count;
  }
  ADD_FAILURE() << "no run parks bay 1";
  return runs;
}

TEST(LevelShortcuts, ChainSecondBayAloneOrTooLateNeverParks) {
  // Level 10: bay 2 counts only after bay 1 is parked (stood in for the hold), and both within
  // the time limit.
  const Scene s = level("level-10-chain");
  ASSERT_TRUE(s.goal.has_value());
  ASSERT_EQ(s.goal->next_bays.size(), 1u);
  const Parsed<Replay> golden =
      loadReplay(std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/level-10-chain.replay");
  ASSERT_TRUE(golden.ok()) << golden.error().toString();
  const ParkingChallenge whole = runChallenge(s, golden.value().runs);
  ASSERT_TRUE(whole.parkedFrame().has_value()) << "the golden drive parks both bays";

  // Through bay 1 without standing there for the hold: the same drive ends in bay 2, which
  // would park as a level of its own, but here bay 1 is still the bay.
  const std::vector<InputRun> rolled = chainWithWaitInBay1(s, golden.value().runs, 20);
  const ParkingChallenge skipped = runChallenge(s, rolled);
  EXPECT_FALSE(skipped.parkedFrame().has_value());
  EXPECT_EQ(skipped.baysParked(), 0u);
  Scene bay2_only = s;
  bay2_only.goal->bay = s.goal->next_bays[0];
  bay2_only.goal->next_bays.clear();
  EXPECT_TRUE(runChallenge(bay2_only, rolled).parkedFrame().has_value())
      << "the drive does end in bay 2: the test is not vacuous";

  // Straight down the lane and nose first into bay 2, at any length of run and turn.
  for (int run = 100; run <= 700; run += 50) {
    for (int turn = 100; turn <= 400; turn += 50) {
      EXPECT_FALSE(parks(s, {{"U", run}, {"UR", turn}, {"U", 60}, {"D", 0}})) << run << " " << turn;
    }
  }

  // Too slow: 30 s more standing in bay 1, and the time is up before bay 2.
  const ParkingChallenge late =
      runChallenge(s, chainWithWaitInBay1(s, golden.value().runs, 75 + 30 * golden.value().hz));
  EXPECT_TRUE(late.timedOut());
  EXPECT_EQ(late.baysParked(), 1u);
  EXPECT_FALSE(late.parkedFrame().has_value());
}

}  // namespace
}  // namespace cardemo::level_shortcuts_test
