// The bundled replays run with the lab's schemes through the library (the studies' way in; the
// cardemo binary runs only the game's): the same outcome, other work.

#include <gtest/gtest.h>

#include <string>

#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "lab/sim/collision_schemes.hpp"

namespace cardemo {
namespace {

std::string asset(const std::string& path) {
  return std::string(CARDEMO_SOURCE_DIR) + "/assets/" + path;
}

// The replay run to its end with `schemes`, its expectations checked.
World runReplay(const std::string& name, const SimulationSchemes& schemes) {
  const std::string path = asset("replays/" + name + ".replay");
  const Parsed<Replay> replay = loadReplay(path);
  EXPECT_TRUE(replay.ok()) << replay.error().toString();
  Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  EXPECT_TRUE(scene.ok()) << scene.error().toString();
  WorldSettings settings = settingsForReplay(replay.value());
  settings.schemes = schemes;
  World world(std::move(scene).value(), settings);
  runReplayInputs(world, replay.value());
  EXPECT_TRUE(checkExpectations(replay.value(), world).empty()) << name;
  return world;
}

TEST(ReplaySchemes, RotationProofBroadPhaseChangesWorkNotResults) {
  SimulationSchemes rotation_proof;
  rotation_proof.query_box = rotationProofBox;
  for (const char* name : {"demo", "scrape", "garage", "reverse"}) {
    const World tight = runReplay(name, {});
    const World loose = runReplay(name, rotation_proof);
    EXPECT_EQ(tight.stateHash(), loose.stateHash()) << name;
    EXPECT_EQ(tight.health(), loose.health()) << name;
    EXPECT_GE(loose.stats().broadphase_candidates, tight.stats().broadphase_candidates) << name;
  }
}

TEST(ReplaySchemes, CollisionModes) {
  // 300 m/s at 30 Hz: the game's scheme sweeps, the sub-stepped one sub-steps, the discrete one
  // does neither; all three meet this replay's expectations (its kerb lies where a step ends).
  SimulationSchemes substepped, discrete;
  substepped.motion = moveSubstepped;
  discrete.motion = moveDiscrete;
  const World continuous = runReplay("highspeed", {});
  const World sub = runReplay("highspeed", substepped);
  const World one_test = runReplay("highspeed", discrete);
  EXPECT_GT(continuous.stats().sweeps, 0);
  EXPECT_EQ(continuous.stats().substeps, 0);
  EXPECT_GT(sub.stats().substeps, 0);
  EXPECT_EQ(sub.stats().sweeps, 0);
  EXPECT_EQ(one_test.stats().substeps, 0);
  EXPECT_EQ(one_test.stats().sweeps, 0);
}

}  // namespace
}  // namespace cardemo
