#include "collision/broad_phase.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

namespace cardemo {
namespace {

Aabb2 box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y1}};
}

// A parking-lot-like scene: mostly car-sized boxes, some small and long ones, a few huge obstacles.
std::vector<Aabb2> randomScene(std::size_t n, std::mt19937_64& rng) {
  const double side = 10.0 * std::sqrt(static_cast<double>(n) + 1.0);
  std::uniform_real_distribution<double> pos(-side, side);
  std::uniform_real_distribution<double> car(1.5, 5.0);
  std::uniform_real_distribution<double> small(0.0, 0.5);
  std::uniform_int_distribution<int> kind(0, 99);
  std::vector<Aabb2> boxes;
  boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = pos(rng), y = pos(rng);
    const int k = kind(rng);
    double w = car(rng), h = car(rng);
    if (k < 10) w = small(rng), h = small(rng);  // kerbs, posts, points
    if (k >= 10 && k < 13) w *= 10.0;            // long walls
    if (k == 99 && i % 7 == 0) w = h = side;     // a few huge obstacles
    boxes.push_back(box(x, y, x + w, y + h));
  }
  return boxes;
}

Aabb2 randomQuery(const std::vector<Aabb2>& scene, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Aabb2 world = scene.empty() ? box(-10, -10, 10, 10) : scene[0];
  for (const Aabb2& b : scene) world = world.merged(b);
  const Eigen::Vector2d size = world.size();
  const int k = kind(rng);
  Eigen::Vector2d c{world.min.x() + unit(rng) * size.x(), world.min.y() + unit(rng) * size.y()};
  if (k == 0) c += Eigen::Vector2d(3.0 * size.x() + 100.0, 0.0);  // far outside
  if (k == 1) c = world.min - Eigen::Vector2d(1.0, 1.0);          // straddling a corner
  if (k == 2 && !scene.empty()) {                                 // exactly touching a box
    const Aabb2& b = scene[static_cast<std::size_t>(unit(rng) * static_cast<double>(scene.size())) %
                           scene.size()];
    return box(b.max.x(), b.max.y(), b.max.x() + 3.0, b.max.y() + 1.0);
  }
  const double w = k == 3 ? 0.0 : 5.0 * unit(rng) + (k == 4 ? 50.0 : 0.0);
  const double h = k == 3 ? 0.0 : 5.0 * unit(rng);
  return box(c.x(), c.y(), c.x() + w, c.y() + h);
}

TEST(BroadPhase, GridMatchesBruteForceOnSeededScenes) {
  for (const std::size_t n : {0u, 1u, 10u, 1000u, 100000u}) {
    for (std::uint64_t seed = 1; seed <= (n >= 100000 ? 2u : 8u); ++seed) {
      std::mt19937_64 rng(seed * 7919 + n);
      const std::vector<Aabb2> scene = randomScene(n, rng);
      const UniformGrid grid(scene);
      const BruteForceBroadPhase brute(scene);
      ASSERT_EQ(grid.size(), n);
      std::vector<std::uint32_t> got, want;
      int nonempty = 0;
      for (int q = 0; q < 300; ++q) {
        const Aabb2 query = randomQuery(scene, rng);
        grid.query(query, got);
        brute.query(query, want);
        ASSERT_EQ(got, want) << "n=" << n << " seed=" << seed << " query " << q << " ["
                             << query.min.transpose() << "] - [" << query.max.transpose() << "]";
        nonempty += want.empty() ? 0 : 1;
      }
      if (n >= 10) {
        EXPECT_GT(nonempty, 30) << "n=" << n << ": the scenes must exercise real hits";
      }
    }
  }
}

TEST(BroadPhase, TouchingBoxesCountAndResultsAreSortedUnique) {
  const std::vector<Aabb2> scene{box(0, 0, 10, 10), box(10, 0, 12, 1), box(-3, -3, 0, 0),
                                 box(20, 20, 21, 21), box(0, 0, 30, 30)};
  const UniformGrid grid(scene);
  std::vector<std::uint32_t> out;
  grid.query(box(10, 10, 10, 10), out);  // a point on the corner of box 0
  EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 4}));
  grid.query(box(12, 1, 20, 20), out);  // touches box 1's corner and box 3's corner
  EXPECT_EQ(out, (std::vector<std::uint32_t>{1, 3, 4}));
  grid.query(box(-100, -100, 100, 100), out);
  EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  grid.query(box(30.000001, 0, 40, 1), out);
  EXPECT_TRUE(out.empty());
}

TEST(BroadPhase, EmptyAndFarQueriesReturnNothing) {
  const UniformGrid empty(std::span<const Aabb2>{});
  std::vector<std::uint32_t> out{1, 2, 3};
  empty.query(box(-1, -1, 1, 1), out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(empty.size(), 0u);

  const std::vector<Aabb2> scene{box(0, 0, 1, 1)};
  const UniformGrid grid(scene);
  out = {7};
  grid.query(box(1e300, 1e300, 1e301, 1e301), out);
  EXPECT_TRUE(out.empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  grid.query(box(nan, nan, nan, nan), out);
  EXPECT_TRUE(out.empty());
}

TEST(BroadPhase, HugeCoordinatesDoNotOverflowCellIndices) {
  const double big = 1e300;
  const std::vector<Aabb2> scene{box(-big, -big, -big + 1e290, -big + 1e290), box(0, 0, 1, 1),
                                 box(big - 1e290, big - 1e290, big, big), box(2, 2, 3, 3)};
  const UniformGrid grid(scene);
  const BruteForceBroadPhase brute(scene);
  std::vector<std::uint32_t> got, want;
  for (const Aabb2& q :
       {box(0.5, 0.5, 2.5, 2.5), box(-big, -big, big, big), box(big, big, big, big),
        box(-1.7e308, -1.7e308, -1e308, -1e308), box(1, 1, 2, 2)}) {
    grid.query(q, got);
    brute.query(q, want);
    EXPECT_EQ(got, want);
  }
}

TEST(BroadPhase, FarFromOriginMatchesBruteForce) {
  std::mt19937_64 rng(42);
  std::vector<Aabb2> scene = randomScene(2000, rng);
  for (Aabb2& b : scene) {
    b.min += Eigen::Vector2d(1e7, -1e7);
    b.max += Eigen::Vector2d(1e7, -1e7);
  }
  const UniformGrid grid(scene);
  const BruteForceBroadPhase brute(scene);
  std::vector<std::uint32_t> got, want;
  for (int q = 0; q < 500; ++q) {
    const Aabb2 query = randomQuery(scene, rng);
    grid.query(query, got);
    brute.query(query, want);
    ASSERT_EQ(got, want) << "query " << q;
  }
}

TEST(BroadPhase, MemoryStaysLinearEvenWithHugeAndSparseBoxes) {
  for (const std::size_t n : {10u, 1000u, 100000u}) {
    std::mt19937_64 rng(n);
    std::vector<Aabb2> scene = randomScene(n, rng);
    // A very sparse outlier stretches the bounds a million-fold: the cell count must stay bounded.
    scene.push_back(box(1e9, 1e9, 1e9 + 4, 1e9 + 2));
    const UniformGrid grid(scene);
    const double per_item = static_cast<double>(grid.memoryBytes()) / static_cast<double>(n + 1);
    // boxes (32 B) + stamp (4 B) + <= 4N+16 offsets (16 B) + a few cells per item.
    EXPECT_LT(per_item, 160.0) << "n=" << n;
    EXPECT_GT(grid.memoryBytes(), (n + 1) * sizeof(Aabb2));
  }
}

TEST(BroadPhase, QueryDoesNotReallocateOnceWarm) {
  std::mt19937_64 rng(3);
  const std::vector<Aabb2> scene = randomScene(5000, rng);
  const UniformGrid grid(scene);
  std::vector<std::uint32_t> out;
  out.reserve(scene.size());
  const std::uint32_t* data = out.data();
  for (int q = 0; q < 1000; ++q) grid.query(randomQuery(scene, rng), out);
  EXPECT_EQ(out.data(), data);
}

TEST(BroadPhase, RepeatedQueriesStayDeduped) {
  // Many queries on a tiny grid: results stay identical, each id once.
  const std::vector<Aabb2> scene{box(0, 0, 100, 100), box(1, 1, 2, 2)};
  const UniformGrid grid(scene);
  std::vector<std::uint32_t> out;
  for (int q = 0; q < 100000; ++q) {
    grid.query(box(0, 0, 3, 3), out);
    ASSERT_EQ(out, (std::vector<std::uint32_t>{0, 1}));
  }
}

}  // namespace
}  // namespace cardemo
