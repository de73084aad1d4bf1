#include <gtest/gtest.h>

#include <sstream>

#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

std::string describe(const HitEvent& h) {
  std::ostringstream s;
  s << "{frame " << h.frame << ", id " << h.id << "}";
  return s.str();
}

TEST(WorldDeterminism, IdenticalRunsGiveIdenticalHashes) {
  const Scene scene = test::parkingLot(11);
  const std::vector<InputFrame> drive = test::scriptedDrive(11, 4000);
  World a(scene), b(scene);
  EXPECT_EQ(a.stateHash(), b.stateHash());
  for (const InputFrame& in : drive) {
    a.step(in);
    b.step(in);
    ASSERT_EQ(a.stateHash(), b.stateHash()) << "frame " << a.frame();
  }
  EXPECT_GT(a.hits().size(), 0u);
  // The hash depends on the state: one more step changes it.
  const std::uint64_t before = a.stateHash();
  a.step(InputFrame{true, false, false, false});
  EXPECT_NE(a.stateHash(), before);
}

TEST(WorldDeterminism, HashHexIsSixteenLowercaseDigits) {
  EXPECT_EQ(hashHex(0), "0000000000000000");
  EXPECT_EQ(hashHex(0x9f3c0e1d2b4a6c58ull), "9f3c0e1d2b4a6c58");
  EXPECT_EQ(hashHex(~0ull), "ffffffffffffffff");
}

TEST(WorldDeterminism, HashOfAFreshWorldIsFnv1aOfItsFields) {
  // Frame 0 at the origin, heading 0: fixed bytes, so the value is pinned here.
  World w(test::sceneWith({}));
  std::uint64_t h = 14695981039346656037ull;
  auto feed = [&h](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  const std::uint64_t one = 0x3ff0000000000000ull;  // bits of 1.0
  // frame, x, y, heading, direction x, y, speed, steer, slip, surface normal x, y, health, hits,
  // then (no contacts) scrape frames, scrape damage, crashes (and no open crash window), then the
  // controls: Up's press, Down's press (both released) and the steering hold.
  const std::uint64_t fields[] = {0, 0, 0, 0, one, 0, 0, 0, 0, 0, 0, 100, 0, 0, 0, 0, 0, 0, 0};
  for (const std::uint64_t v : fields) feed(v);
  EXPECT_EQ(w.stateHash(), h) << hashHex(w.stateHash()) << " vs " << hashHex(h);
}

TEST(WorldDeterminism, TranslatedSceneGivesTheSameHits) {
  for (const std::uint64_t seed : {21u, 22u, 24u, 25u, 26u}) {
    const Scene scene = test::parkingLot(seed);
    const Scene moved = test::translated(scene, {1e7, -1e7});
    World a(scene), b(moved);
    std::size_t compared = 0;
    for (const InputFrame& in : test::scriptedDrive(seed, 4000)) {
      a.step(in);
      b.step(in);
      const auto& ha = a.hits();
      const auto& hb = b.hits();
      for (; compared < std::max(ha.size(), hb.size()); ++compared) {
        ASSERT_LT(compared, ha.size())
            << "seed " << seed << ": first divergence at frame " << a.frame()
            << ": only the translated run hit " << describe(hb[compared]);
        ASSERT_LT(compared, hb.size())
            << "seed " << seed << ": first divergence at frame " << a.frame()
            << ": only the original run hit " << describe(ha[compared]);
        ASSERT_EQ(describe(ha[compared]), describe(hb[compared]))
            << "seed " << seed << ": first divergence at frame " << a.frame();
      }
    }
    EXPECT_GT(a.hits().size(), 0u) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cardemo
