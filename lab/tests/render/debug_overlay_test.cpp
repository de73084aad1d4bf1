// The debug overlay shows the broad-phase box the world queries, also a study's (lab/sim).

#include "render/debug_overlay.hpp"

#include <gtest/gtest.h>

#include "lab/sim/collision_schemes.hpp"
#include "tests/sim/scene_builders.hpp"

namespace cardemo {
namespace {

using test::sceneWith;

TEST(DrawWorld, RotationProofBroadPhaseBoxIsTheOneShown) {
  WorldSettings settings;
  settings.schemes.query_box = rotationProofBox;
  World world(sceneWith({}, 0.0, 0.0, 30.0), settings);
  const Aabb2 b = broadPhaseBox(world);
  EXPECT_EQ(b, rotationProofBox(world.carBox()));
  World tight(sceneWith({}, 0.0, 0.0, 30.0));
  EXPECT_EQ(broadPhaseBox(tight), tight.carBox().aabb());
}

}  // namespace
}  // namespace cardemo
