// The lab's vector forms of the one-pair 3D queries against src's, bit for bit, on every path.

#include "lab/geometry/obb3_paths.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <vector>

#include "tests/geometry/random_cases3.hpp"
#include "tests/support/batch_paths.hpp"

namespace cardemo {
namespace {

using test3::describe;
using test3::Pair3;

// The lab's vector forms of overlapObb3 and collideObb3: on every path the same bits as src's,
// over every kind of pair the random classes draw and frames off a rotation.
TEST(Obb3FastPath, EveryPathGivesTheSameBits) {
  testing::BatchPathGuard guard;
  const std::vector<BatchPath> paths = testing::availableBatchPaths();
  const std::function<Pair3(std::mt19937_64&)> kinds[] = {
      test3::gapPair,      test3::farPair,
      test3::sizePair,     [](std::mt19937_64& rng) { return test3::nearParallelPair(rng); },
      test3::parallelPair, test3::containmentPair,
      test3::touchingPair, test3::coincidentPair};
  std::mt19937_64 rng(0x0b3a0300);
  for (int k = 0; k < 40000; ++k) {
    Pair3 p = kinds[k % 8](rng);
    if (k % 5 == 0) {  // off a rotation: 1e-12 (a wider bound) or 1e-9 (no filter)
      const double eps = k % 10 == 0 ? 1e-12 : 1e-9;
      Eigen::Matrix3d m = p.b.rotation();
      for (int e = 0; e < 9; ++e) m(e / 3, e % 3) += eps * test3::uniform(rng, -1, 1);
      p.b.setRotation(m);
    }
    const SatResult3 want = collideObb3(p.a, p.b);
    const bool want_overlap = overlapObb3(p.a, p.b);
    for (const BatchPath path : paths) {
      setBatchPath(path);
      const SatResult3 got = collideObb3OnPath(p.a, p.b);
      ASSERT_EQ(overlapObb3OnPath(p.a, p.b), want_overlap)
          << "pair " << k << " on " << batchPathName(path);
      ASSERT_TRUE(got.hit == want.hit && got.axis_index == want.axis_index &&
                  testing::sameBits(got.separation, want.separation) &&
                  testing::sameBits(got.normal.x(), want.normal.x()) &&
                  testing::sameBits(got.normal.y(), want.normal.y()) &&
                  testing::sameBits(got.normal.z(), want.normal.z()))
          << "pair " << k << " on " << batchPathName(path) << ": axis " << got.axis_index << " sep "
          << got.separation << " against axis " << want.axis_index << " sep " << want.separation
          << "\n"
          << describe(p.a, p.b);
    }
  }
}

}  // namespace
}  // namespace cardemo
