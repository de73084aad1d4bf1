// The lab's collision schemes (discrete, sub-stepped) and the rotation-proof broad-phase box,
// driven through World's scheme policy, against the game's continuous scheme and tight box.

#include "lab/sim/collision_schemes.hpp"

#include <gtest/gtest.h>

#include "tests/sim/drive_into.hpp"
#include "tests/sim/key_frames.hpp"
#include "tests/sim/scene_builders.hpp"

namespace cardemo {
namespace {

using test::driveInto;
using test::kerbAcross;
using test::Target;
using testing::kNone;

TEST(WorldContinuous, SlowStepsTakeTheDiscretePathExactly) {
  // At ordinary speeds the three modes agree bit for bit and nothing is swept or sub-stepped.
  const Scene scene = test::parkingLot(13);
  WorldSettings continuous, substepped, discrete;
  substepped.schemes.motion = moveSubstepped;
  discrete.schemes.motion = moveDiscrete;
  World a(scene, continuous), b(scene, substepped), c(scene, discrete);
  for (const InputFrame& in : test::scriptedDrive(13, 3000)) {
    a.step(in);
    b.step(in);
    c.step(in);
    ASSERT_EQ(a.stateHash(), b.stateHash()) << "frame " << a.frame();
    ASSERT_EQ(a.stateHash(), c.stateHash()) << "frame " << a.frame();
  }
  EXPECT_GT(a.hits().size(), 0u);
  EXPECT_EQ(a.stats().sweeps, 0);
  EXPECT_EQ(a.stats().substeps, 0);
  EXPECT_EQ(b.stats().substeps, 0);
}

TEST(WorldContinuous, DiscreteModeTunnelsWhereTheOthersDoNot) {
  // 300 m/s at 30 Hz: 10 m per step over a 5 cm kerb.
  const Target t = kerbAcross(0.0, 0.0, 25.0);
  EXPECT_NE(driveInto(t, 0.0, 300.0, 30.0, moveDiscrete, kNone, 10), "");
  EXPECT_EQ(driveInto(t, 0.0, 300.0, 30.0, moveSubstepped, kNone, 10), "");
  EXPECT_EQ(driveInto(t, 0.0, 300.0, 30.0, nullptr, kNone, 10), "");
}

TEST(World, RotationProofBoxGivesTheSameHitsWithMoreCandidates) {
  const Scene scene = test::parkingLot(11);
  WorldSettings proof;
  proof.schemes.query_box = rotationProofBox;
  World tight(scene);
  World wide(scene, proof);
  for (const InputFrame& in : test::scriptedDrive(11, 4000)) {
    tight.step(in);
    wide.step(in);
  }
  ASSERT_GT(tight.hits().size(), 0u);
  ASSERT_EQ(tight.hits().size(), wide.hits().size());
  for (std::size_t i = 0; i < tight.hits().size(); ++i) {
    EXPECT_EQ(tight.hits()[i].frame, wide.hits()[i].frame);
    EXPECT_EQ(tight.hits()[i].id, wide.hits()[i].id);
  }
  EXPECT_EQ(tight.stateHash(), wide.stateHash());
  EXPECT_GE(wide.stats().broadphase_candidates, tight.stats().broadphase_candidates);
}

}  // namespace
}  // namespace cardemo
