// The lab's quadrilateral SAT against src's collidePolygons, bit for bit, on every batch path.

#include "lab/geometry/collide_quads.hpp"

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "tests/geometry/shape_pairs.hpp"
#include "tests/support/batch_paths.hpp"

namespace cardemo {
namespace {

using testing::quadrilateralPair;
using testing::Random;
using testing::tiedSquares;

// The quadrilateral fast path has an SSE2, an AVX2 and an AVX-512VL form: on every path the same
// bits as src's collidePolygons, also where the fast range ends (huge coordinates, tiny edges) and
// the general path takes over, and where axes tie for the largest gap.
TEST(ConvexPolygonSat, QuadrilateralsGiveTheSameBitsOnEveryPath) {
  testing::BatchPathGuard guard;
  const std::vector<BatchPath> paths = testing::availableBatchPaths();
  Random rng(2007);
  for (int i = 0; i < 20000; ++i) {
    auto [a, b] = quadrilateralPair(rng);
    if (i % 10 == 1) {  // past kLargestFastCoordinate relative to A's first vertex
      b.translate(rng.direction() * 0x1p101);
    } else if (i % 10 == 2) {  // edges below 1e-30 m: squared lengths below kSmallestFastLength2
      ConvexPolygon tiny = a.poly;
      for (int k = 0; k < 4; ++k) {
        tiny.vertices[static_cast<std::size_t>(k)] =
            a.poly.vertex(0) + (a.poly.vertex(k) - a.poly.vertex(0)) * 1e-32;
      }
      a.poly = tiny;
    } else if (i % 10 == 3) {
      std::tie(a.poly, b.poly) = tiedSquares(rng);
    }
    const SatResult2 want = collidePolygons(a.poly, b.poly);
    for (const BatchPath path : paths) {
      setBatchPath(path);
      const SatResult2 got = collideQuads(a.poly, b.poly);
      ASSERT_TRUE(got.hit == want.hit && testing::sameBits(got.separation, want.separation) &&
                  testing::sameBits(got.normal.x(), want.normal.x()) &&
                  testing::sameBits(got.normal.y(), want.normal.y()))
          << "pair " << i << " on " << batchPathName(path) << ": " << got.separation << " against "
          << want.separation;
    }
  }
}

}  // namespace
}  // namespace cardemo
