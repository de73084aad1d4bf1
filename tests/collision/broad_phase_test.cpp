#include "collision/broad_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../support/batch_paths.hpp"
#include "geometry/batch_path.hpp"

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

// Rows of parked cars like assets/scenes/large-lot.json (scripts/make_large_lot.py): jittered
// headings near 90/270 degrees, 3% empty bays, aisles between double rows.
std::vector<Aabb2> lotScene(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Aabb2> boxes;
  for (std::size_t bay = 0; boxes.size() < n; ++bay) {
    if (unit(rng) < 0.03) continue;
    const std::size_t row = bay / 104, k = bay % 104;
    const double y = static_cast<double>(row / 2) * 16.2 + (row % 2 == 0 ? 5.8 : -5.8);
    const double heading = (row % 2 == 0 ? 90.0 : 270.0) + (unit(rng) - 0.5) * 6.0;
    const Eigen::Vector2d c{static_cast<double>(k) * 2.6 + (unit(rng) - 0.5) * 0.3, y};
    const double t = heading * 3.14159265358979323846 / 180.0;
    const double len = 4.2 + 0.6 * unit(rng), wid = 1.7 + 0.2 * unit(rng);
    const Eigen::Vector2d r{0.5 * (std::abs(std::cos(t)) * len + std::abs(std::sin(t)) * wid),
                            0.5 * (std::abs(std::sin(t)) * len + std::abs(std::cos(t)) * wid)};
    boxes.push_back({c - r, c + r});
  }
  return boxes;
}

void expectTwins(const std::vector<Aabb2>& scene, const std::vector<Aabb2>& queries,
                 const char* what) {
  const UniformGrid grid(scene);
  const BruteForceBroadPhase brute(scene);
  std::vector<std::uint32_t> got, want;
  // One QueryIds across every query, so that crowded queries (the buffered scan) and the few-ids
  // path follow each other in the same storage.
  QueryIds ids;
  testing::BatchPathGuard guard;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    for (std::size_t q = 0; q < queries.size(); ++q) {
      grid.query(queries[q], got);
      brute.query(queries[q], want);
      ASSERT_EQ(got, want) << what << " on " << batchPathName(path) << ": query " << q << " ["
                           << queries[q].min.transpose() << "] - [" << queries[q].max.transpose()
                           << "]";
      grid.query(queries[q], ids);
      ASSERT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.end()), want)
          << what << " on " << batchPathName(path) << ", QueryIds: query " << q;
      ASSERT_EQ(ids.size(), want.size());
      ASSERT_EQ(ids.empty(), want.empty());
      ASSERT_EQ(ids.ids().size(), want.size());
    }
  }
}

TEST(BroadPhase, LotLayoutWithAMovingCarMatchesBruteForce) {
  for (const std::size_t n : {100u, 5000u, 60000u}) {
    std::mt19937_64 rng(n);
    const std::vector<Aabb2> scene = lotScene(n, rng);
    Aabb2 world = scene[0];
    for (const Aabb2& b : scene) world = world.merged(b);
    // A car-sized box driving up and down the lot in 0.25 m steps, turning as it goes.
    std::vector<Aabb2> queries;
    for (int step = 0; step < 4000; ++step) {
      const double s = 0.25 * step;
      const Eigen::Vector2d c{world.min.x() - 5.0 + std::fmod(s * 0.9, world.size().x() + 10.0),
                              world.min.y() - 5.0 + std::fmod(s * 0.37, world.size().y() + 10.0)};
      const double t = 0.01 * step;
      const Eigen::Vector2d r{0.5 * (std::abs(std::cos(t)) * 4.5 + std::abs(std::sin(t)) * 1.8),
                              0.5 * (std::abs(std::sin(t)) * 4.5 + std::abs(std::cos(t)) * 1.8)};
      queries.push_back({c - r, c + r});
    }
    expectTwins(scene, queries, "lot");
    const UniformGrid grid(scene);
    EXPECT_EQ(grid.levelCount(), 1u) << "a lot of similar cars is one size class";
  }
}

TEST(BroadPhase, ExactTouchingAtTheEdgeOfTheScanIsFound) {
  // Dyadic boxes whose right edge lands exactly on the query's left edge: the widest box of the
  // level decides how far left the scan starts, so it must reach them exactly.
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> grid_units(0, 4000);
  std::uniform_int_distribution<int> size_units(1, 40);
  std::vector<Aabb2> scene;
  for (int i = 0; i < 3000; ++i) {
    const double x = grid_units(rng) / 16.0, y = grid_units(rng) / 16.0;
    const double w = size_units(rng) / 16.0;
    const double h = size_units(rng) / 16.0;
    scene.push_back(box(x, y, x + w, y + h));
  }
  std::vector<Aabb2> queries;
  for (const Aabb2& b : scene) {
    queries.push_back(box(b.max.x(), b.max.y(), b.max.x() + 0.5, b.max.y() + 0.5));
    queries.push_back(box(b.max.x(), b.min.y(), b.max.x(), b.min.y()));  // a point on the edge
    queries.push_back(box(b.min.x() - 1.0, b.max.y(), b.min.x(), b.max.y() + 1.0));
  }
  expectTwins(scene, queries, "touching");
}

TEST(BroadPhase, MixedSizesUseSeveralLevelsAndOversizedItems) {
  // Extents from 1 mm to 1e5 m: several size classes plus the oversized list.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-2000.0, 2000.0);
  std::uniform_real_distribution<double> exponent(-3.0, 5.0);
  std::vector<Aabb2> scene;
  for (int i = 0; i < 20000; ++i) {
    const double x = pos(rng), y = pos(rng);
    const double w = std::pow(10.0, exponent(rng)) * (i % 3 == 0 ? 0.0 : 1.0);  // some lines
    const double h = std::pow(10.0, exponent(rng));
    scene.push_back(box(x, y, x + w, y + h));
  }
  std::vector<Aabb2> queries;
  for (int q = 0; q < 3000; ++q) {
    const double x = pos(rng), y = pos(rng);
    const double w = std::pow(10.0, exponent(rng) - 1.0);
    queries.push_back(box(x, y, x + w, y + 0.5 * w));
  }
  expectTwins(scene, queries, "mixed");
  EXPECT_GT(UniformGrid(scene).levelCount(), 3u);
}

TEST(BroadPhase, CrowdedCellsLongerThanTheQueryBuffer) {
  // 2000 identical boxes, 500 points at one spot and a line of boxes: runs of hundreds of ids.
  std::vector<Aabb2> scene(2000, box(1, 1, 3, 2));
  for (int i = 0; i < 500; ++i) scene.push_back(box(2, 1.5, 2, 1.5));
  for (int i = 0; i < 700; ++i) scene.push_back(box(i * 0.01, 1.0, i * 0.01 + 0.5, 1.0));
  std::vector<Aabb2> queries{box(0, 0, 4, 4),  box(2, 1.5, 2, 1.5), box(3, 2, 5, 5),
                             box(-1, 1, 0, 1), box(3.01, 0, 9, 9),  box(2.5, 0.5, 2.6, 1.0)};
  expectTwins(scene, queries, "crowded");
  // Only points, all at one spot; and all on one vertical line.
  expectTwins(std::vector<Aabb2>(300, box(7, 7, 7, 7)), {box(7, 7, 7, 7), box(6, 6, 6.9, 8)},
              "points");
  std::vector<Aabb2> line;
  for (int i = 0; i < 300; ++i) line.push_back(box(1, i, 1, i + 0.5));
  expectTwins(line, {box(0, 10, 2, 10), box(1, 10.6, 1, 10.9), box(1, -5, 1, 500)}, "line");
}

TEST(BroadPhase, LotLayoutStaysUnder64BytesPerCar) {
  // The benchmark's memory target, as a deterministic property of the layout.
  for (const std::size_t n : {1000u, 100000u}) {
    std::mt19937_64 rng(n + 1);
    const std::vector<Aabb2> scene = lotScene(n, rng);
    const UniformGrid grid(scene);
    EXPECT_LE(static_cast<double>(grid.memoryBytes()) / static_cast<double>(n), 64.0) << n;
  }
}

TEST(BroadPhase, GridMatchesBruteForceOnSeededScenes) {
  for (const std::size_t n : {0u, 1u, 10u, 1000u, 100000u}) {
    for (std::uint64_t seed = 1; seed <= (n >= 100000 ? 2u : 8u); ++seed) {
      std::mt19937_64 rng(seed * 7919 + n);
      const std::vector<Aabb2> scene = randomScene(n, rng);
      const UniformGrid grid(scene);
      ASSERT_EQ(grid.size(), n);
      // Walls and posts beside the cars: several size classes, so the scans' loop over levels
      // runs (with no oversized item, also that of the few-ids scan).
      if (n >= 1000) {
        EXPECT_GT(grid.levelCount(), 2u) << "n=" << n;
      }
      const BruteForceBroadPhase brute(scene);
      std::vector<Aabb2> queries;
      std::vector<std::uint32_t> want;
      int nonempty = 0;
      for (int q = 0; q < 300; ++q) {
        queries.push_back(randomQuery(scene, rng));
        brute.query(queries.back(), want);
        nonempty += want.empty() ? 0 : 1;
      }
      if (n >= 10) {
        EXPECT_GT(nonempty, 30) << "n=" << n << ": the scenes must exercise real hits";
      }
      const std::string what = "n=" + std::to_string(n) + " seed=" + std::to_string(seed);
      expectTwins(scene, queries, what.c_str());
    }
  }
}

TEST(BroadPhase, TallQueriesOverManyRowsOfOneLevelMatchBruteForce) {
  // One level of equal boxes, and thin queries whose windows span more rows than the scans take
  // from one word of row bits (56), finding only a few boxes: the AVX2 scan's path for several
  // words, beside its one-word path for the short queries.
  std::mt19937_64 rng(56);
  std::uniform_real_distribution<double> pos(0.0, 1000.0), unit(0.0, 1.0);
  std::vector<Aabb2> scene;
  for (int k = 0; k < 2000; ++k) {
    const double x = pos(rng), y = pos(rng);
    scene.push_back(box(x, y, x + 1.0, y + 1.0));
  }
  std::vector<Aabb2> queries;
  for (int q = 0; q < 400; ++q) {
    const double x = pos(rng), y = pos(rng);
    const double height = q % 2 == 0 ? 1000.0 * unit(rng) : 3.0 * unit(rng);
    queries.push_back(box(x, y - height, x + 0.2 * unit(rng), y + height));
  }
  const UniformGrid grid(scene);
  ASSERT_EQ(grid.levelCount(), 1u);
  expectTwins(scene, queries, "tall");
}

TEST(BroadPhase, CellsAreNoShorterThanTheBoxesMeanReach) {
  // 2,000 boxes of 5 m by 3 m on 100 m by 100 m: the density rule alone (0.7 times the root of
  // the area per box) would give 1.6 m cells, smaller than the 4 m mean reach. The square side is
  // the larger; a narrower shape keeps at least a quarter of it across and is taller.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> pos(0.0, 100.0);
  std::vector<Aabb2> scene;
  for (int k = 0; k < 2000; ++k) {
    const double x = pos(rng), y = pos(rng);
    scene.push_back(box(x, y, x + 5.0, y + 3.0));
  }
  const UniformGrid grid(scene);
  ASSERT_EQ(grid.levelCount(), 1u);
  EXPECT_GE(grid.cellSize(0).y(), 4.0);
  EXPECT_GE(grid.cellSize(0).x(), 1.0);
  std::vector<Aabb2> queries;
  for (int q = 0; q < 300; ++q) queries.push_back(randomQuery(scene, rng));
  expectTwins(scene, queries, "reach-sized cells");
}

// Cars at random places and headings, like the benchmark's random layout: about 14 m^2 each.
std::vector<Aabb2> scatteredCars(std::size_t n, std::mt19937_64& rng) {
  const double side = std::sqrt(14.0 * static_cast<double>(n));
  std::uniform_real_distribution<double> pos(0.0, side), turn(0.0, 6.283185307179586);
  std::vector<Aabb2> boxes;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d c{pos(rng), pos(rng)};
    const double t = turn(rng);
    const Eigen::Vector2d r{0.5 * (std::abs(std::cos(t)) * 4.5 + std::abs(std::sin(t)) * 1.8),
                            0.5 * (std::abs(std::sin(t)) * 4.5 + std::abs(std::cos(t)) * 1.8)};
    boxes.push_back({c - r, c + r});
  }
  return boxes;
}

TEST(BroadPhase, CellShapeFollowsTheLayout) {
  // A large level keeps the cell shape whose estimated scan cost is lowest: in rows of parked cars
  // square cells (each row of cars falls in one or two rows of cells), among scattered cars
  // narrower and taller ones (fewer rows a query, fewer boxes outside its window in each).
  // Either way every query finds what brute force finds.
  std::mt19937_64 rng(12);
  const std::vector<Aabb2> lot = lotScene(50000, rng);
  const std::vector<Aabb2> scattered = scatteredCars(50000, rng);
  const UniformGrid lot_grid(lot), scattered_grid(scattered);
  ASSERT_EQ(lot_grid.levelCount(), 1u);
  ASSERT_EQ(scattered_grid.levelCount(), 1u);
  EXPECT_EQ(lot_grid.cellSize(0).x(), lot_grid.cellSize(0).y());
  EXPECT_LT(scattered_grid.cellSize(0).x(), 0.5 * scattered_grid.cellSize(0).y());
  // Below 32,768 boxes a level keeps square cells without estimating (its build stays cheap).
  const UniformGrid few_scattered(scatteredCars(20000, rng));
  EXPECT_EQ(few_scattered.cellSize(0).x(), few_scattered.cellSize(0).y());
  std::vector<Aabb2> lot_queries, scattered_queries;
  for (int q = 0; q < 2000; ++q) {
    lot_queries.push_back(randomQuery(lot, rng));
    scattered_queries.push_back(randomQuery(scattered, rng));
  }
  expectTwins(lot, lot_queries, "lot, square cells");
  expectTwins(scattered, scattered_queries, "scattered cars, narrow cells");
}

TEST(BroadPhase, TouchingBoxesCountAndResultsAreSortedUnique) {
  const std::vector<Aabb2> scene{box(0, 0, 10, 10), box(10, 0, 12, 1), box(-3, -3, 0, 0),
                                 box(20, 20, 21, 21), box(0, 0, 30, 30)};
  const UniformGrid grid(scene);
  std::vector<std::uint32_t> out;
  testing::BatchPathGuard guard;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    SCOPED_TRACE(batchPathName(path));
    grid.query(box(10, 10, 10, 10), out);  // a point on the corner of box 0
    EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 4}));
    grid.query(box(12, 1, 20, 20), out);  // touches box 1's corner and box 3's corner
    EXPECT_EQ(out, (std::vector<std::uint32_t>{1, 3, 4}));
    grid.query(box(-100, -100, 100, 100), out);
    EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    grid.query(box(30.000001, 0, 40, 1), out);
    EXPECT_TRUE(out.empty());
  }
}

TEST(BroadPhase, EmptyAndFarQueriesReturnNothing) {
  testing::BatchPathGuard guard;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    SCOPED_TRACE(batchPathName(path));
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
    // NaN in any one coordinate (each is compared by a different test of the scan).
    const std::vector<Aabb2> one_nan{box(nan, 0, 1, 1), box(0, nan, 1, 1), box(0, 0, nan, 1),
                                     box(0, 0, 1, nan)};
    QueryIds ids;
    for (const Aabb2& query : one_nan) {
      grid.query(query, out);
      EXPECT_TRUE(out.empty()) << query.min.transpose() << " " << query.max.transpose();
      grid.query(query, ids);
      EXPECT_TRUE(ids.empty()) << query.min.transpose() << " " << query.max.transpose();
    }
  }
}

// A scan step reads past the end of a row's boxes into the padding after it; an infinite query
// (which an infinite padding box would pass) must still find each box once.
TEST(BroadPhase, InfiniteQueriesFindEachBoxOnce) {
  testing::BatchPathGuard guard;
  const double inf = std::numeric_limits<double>::infinity();
  // Eight boxes or fewer (the few-ids scan) and more, over several rows of cells.
  for (const std::size_t n : {1u, 3u, 8u, 9u, 40u}) {
    std::vector<Aabb2> scene;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i % 3) * 7.0, y = static_cast<double>(i / 3) * 9.0;
      scene.push_back(box(x, y, x + 4.5, y + 1.8));
    }
    const UniformGrid grid(scene);
    std::vector<std::uint32_t> expected(n);
    for (std::size_t i = 0; i < n; ++i) expected[i] = static_cast<std::uint32_t>(i);
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      SCOPED_TRACE(std::string(batchPathName(path)) + ", " + std::to_string(n) + " boxes");
      for (const Aabb2& query :
           {box(-inf, -inf, inf, inf), box(-inf, -1, inf, 1e9), box(-1, -inf, 1e9, inf)}) {
        std::vector<std::uint32_t> out;
        grid.query(query, out);
        EXPECT_EQ(out, expected);
        QueryIds ids;
        grid.query(query, ids);
        EXPECT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.end()), expected);
      }
    }
  }
}

TEST(BroadPhase, HugeCoordinatesDoNotOverflowCellIndices) {
  const double big = 1e300;
  const std::vector<Aabb2> scene{box(-big, -big, -big + 1e290, -big + 1e290), box(0, 0, 1, 1),
                                 box(big - 1e290, big - 1e290, big, big), box(2, 2, 3, 3)};
  expectTwins(scene,
              {box(0.5, 0.5, 2.5, 2.5), box(-big, -big, big, big), box(big, big, big, big),
               box(-1.7e308, -1.7e308, -1e308, -1e308), box(1, 1, 2, 2)},
              "huge");
}

TEST(BroadPhase, FarFromOriginMatchesBruteForce) {
  std::mt19937_64 rng(42);
  std::vector<Aabb2> scene = randomScene(2000, rng);
  for (Aabb2& b : scene) {
    b.min += Eigen::Vector2d(1e7, -1e7);
    b.max += Eigen::Vector2d(1e7, -1e7);
  }
  std::vector<Aabb2> queries;
  for (int q = 0; q < 500; ++q) queries.push_back(randomQuery(scene, rng));
  expectTwins(scene, queries, "far");
}

TEST(BroadPhase, EveryAvailableScanPathIsTestedAndTheFallbackIsAmongThem) {
  // The twins above run once per path of testing::availableBatchPaths(): check what that list
  // holds, so a machine without AVX2 still runs (and reports) the portable scan, and one with it
  // runs both.
  const std::vector<BatchPath> paths = testing::availableBatchPaths();
  ASSERT_FALSE(paths.empty());
  EXPECT_EQ(paths.front(), BatchPath::kPortable);
  EXPECT_NE(std::find(paths.begin(), paths.end(), batchPath()), paths.end())
      << "the path in use must be one the CPU can run";
  EXPECT_EQ(std::count(paths.begin(), paths.end(), BatchPath::kAvx2),
            batchPathAvailable(BatchPath::kAvx2) ? 1 : 0);
  for (const BatchPath path : paths) std::printf("    scan path %s tested\n", batchPathName(path));
}

TEST(BroadPhase, CopiesAndMovesQueryTheirOwnArrays) {
  std::mt19937_64 rng(11);
  const std::vector<Aabb2> scene = randomScene(3000, rng);
  const BruteForceBroadPhase brute(scene);
  std::vector<Aabb2> queries;
  for (int q = 0; q < 300; ++q) queries.push_back(randomQuery(scene, rng));
  const auto expectMatches = [&](const UniformGrid& grid, const char* what) {
    std::vector<std::uint32_t> got, want;
    QueryIds ids;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      grid.query(queries[q], got);
      brute.query(queries[q], want);
      ASSERT_EQ(got, want) << what << ": query " << q;
      grid.query(queries[q], ids);
      ASSERT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.end()), want)
          << what << ": query " << q;
    }
  };
  // A grid moved from holds nothing: both query forms find nothing (the inline form must not
  // scan views that went with the move).
  const auto expectEmpty = [&](const UniformGrid& grid, const char* what) {
    std::vector<std::uint32_t> got{7};
    QueryIds ids;
    for (const Aabb2& query : queries) {
      grid.query(query, got);
      ASSERT_TRUE(got.empty()) << what;
      grid.query(query, ids);
      ASSERT_TRUE(ids.empty()) << what;
    }
    EXPECT_EQ(grid.size(), 0u) << what;
    EXPECT_EQ(grid.levelCount(), 0u) << what;
  };
  auto original = std::make_unique<UniformGrid>(scene);
  const UniformGrid copy(*original);
  UniformGrid assigned(std::span<const Aabb2>{});
  assigned = *original;
  original.reset();  // the copies must not point into the freed arrays
  expectMatches(copy, "copy");
  expectMatches(assigned, "copy-assigned");
  UniformGrid moved(std::move(assigned));
  expectMatches(moved, "moved");
  expectEmpty(assigned, "moved from");  // NOLINT(bugprone-use-after-move): the state is specified
  UniformGrid move_assigned(std::span<const Aabb2>{});
  move_assigned = std::move(moved);
  expectMatches(move_assigned, "move-assigned");
  expectEmpty(moved, "move-assigned from");  // NOLINT(bugprone-use-after-move)
  EXPECT_EQ(move_assigned.size(), scene.size());
  EXPECT_EQ(move_assigned.memoryBytes(), copy.memoryBytes());
}

TEST(BroadPhase, MemoryStaysLinearEvenWithHugeAndSparseBoxes) {
  for (const std::size_t n : {10u, 1000u, 100000u}) {
    std::mt19937_64 rng(n);
    std::vector<Aabb2> scene = randomScene(n, rng);
    // A very sparse outlier stretches the bounds a million-fold: the cell count must stay bounded.
    scene.push_back(box(1e9, 1e9, 1e9 + 4, 1e9 + 2));
    const UniformGrid grid(scene);
    const double per_item = static_cast<double>(grid.memoryBytes()) / static_cast<double>(n + 1);
    // boxes (32 B) + ids (4 B) + <= 4N+16 offsets (16 B) per level.
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

  QueryIds ids;
  ids.reserve(scene.size());
  const std::uint32_t* ids_data = ids.begin();
  std::size_t crowded = 0;
  for (int q = 0; q < 1000; ++q) {
    // Every 50th query finds every box: the buffered scan, at the reserved size.
    grid.query(q % 50 == 0 ? box(-1e12, -1e12, 1e12, 1e12) : randomQuery(scene, rng), ids);
    crowded += ids.size() > grid_detail::kFewIds ? 1 : 0;
  }
  EXPECT_EQ(ids.begin(), ids_data);
  EXPECT_GT(crowded, 0u) << "some queries must take the buffered scan";
}

TEST(BroadPhase, QueryIdsKeepTheirStorageFromCrowdedToFewIds) {
  // A crowded query (more ids than the register path keeps) and then small ones into the same
  // QueryIds: each answer is exactly its own, on every path.
  std::vector<Aabb2> scene;
  for (int k = 0; k < 40; ++k) scene.push_back(box(k, 0, k + 0.5, 1));
  const UniformGrid grid(scene);
  testing::BatchPathGuard guard;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    SCOPED_TRACE(batchPathName(path));
    QueryIds ids;
    EXPECT_TRUE(ids.empty());
    grid.query(box(-1, -1, 50, 2), ids);
    ASSERT_EQ(ids.size(), 40u);
    for (std::uint32_t k = 0; k < 40; ++k) EXPECT_EQ(ids[k], k);
    grid.query(box(3.25, 0.5, 4.25, 0.5), ids);
    EXPECT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.end()),
              (std::vector<std::uint32_t>{3, 4}));
    grid.query(box(100, 100, 101, 101), ids);
    EXPECT_TRUE(ids.empty());
    EXPECT_EQ(ids.begin(), ids.end());
    grid.query(box(0, 0, 8.75, 1), ids);  // boxes 0-8: one more than the register path keeps
    EXPECT_EQ(ids.size(), 9u);
    grid.query(box(0, 0, 7.75, 1), ids);  // boxes 0-7: exactly as many as it keeps
    EXPECT_EQ(ids.size(), 8u);
    EXPECT_EQ(ids[7], 7u);

    // A moved-from QueryIds (its storage gone) answers the next query all the same.
    QueryIds taken = std::move(ids);
    EXPECT_EQ(taken.size(), 8u);
    EXPECT_TRUE(ids.empty());  // NOLINT(bugprone-use-after-move): the moved-from state is defined
    EXPECT_EQ(ids.begin(), ids.end());
    grid.query(box(3.25, 0.5, 4.25, 0.5), ids);  // NOLINT(bugprone-use-after-move): on purpose
    EXPECT_EQ(std::vector<std::uint32_t>(ids.begin(), ids.end()),
              (std::vector<std::uint32_t>{3, 4}));
  }
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
