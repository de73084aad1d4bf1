/// Batch 2D SAT (one box against many) against the scalar functions (bit for bit), the exact
/// oracle, and itself on both dispatch paths, over seeded random batches and named edge cases.

#include "lab/kernels/obb2_batch.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "geometry/angle.hpp"
#include "geometry/batch_path.hpp"
#include "geometry/sat_obb2.hpp"
#include "tests/geometry/random_cases2.hpp"
#include "tests/support/batch_paths.hpp"

namespace cardemo {
namespace {

using testing::Random;

using testing::sameBits;

// Dyadic value on a 2^-10 grid: sums of such values are exact, so touching is exact.
double dyadic(Random& rng, double lo, double hi) {
  return std::ldexp(std::round(std::ldexp(rng.uniform(lo, hi), 10)), -10);
}

// A box B for query A, from one of several classes: near touching on one of the four axes, at a
// random place, near parallel, exactly touching (axis-aligned, dyadic), contained, extreme sizes.
Obb2 boxFor(const Obb2& a, Random& rng) {
  const int kind = rng.integer(0, 5);
  if (kind == 3 && a.axis == Eigen::Vector2d::UnitX()) {
    Obb2 b{{0, 0}, {1, 0}, {dyadic(rng, 0.25, 10.0), dyadic(rng, 0.25, 10.0)}};
    const double sx = rng.sign(), sy = rng.sign();
    const bool corner = rng.integer(0, 2) == 0;
    const double lateral = dyadic(rng, -0.9, 0.9) * (a.half.y() + b.half.y());
    b.center = a.center + Eigen::Vector2d(sx * (a.half.x() + b.half.x()),
                                          corner ? sy * (a.half.y() + b.half.y()) : lateral);
    if (rng.integer(0, 1) == 0) std::swap(b.center.x(), b.center.y());
    return b;
  }
  Obb2 b = kind == 5 ? rng.extremeBox({0, 0}) : rng.box({0, 0}, 0.1, 20.0);
  if (kind == 2) {
    const int quarters = rng.integer(0, 3);
    const double heading = std::atan2(a.axis.y(), a.axis.x()) + quarters * 0.5 * std::numbers::pi +
                           rng.signedLogUniform(1e-15, 1e-3);
    b.axis = unitFromRadians(heading);
  }
  if (kind == 1) {
    b.center = a.center + rng.offset(0.0, 1.2 * (a.half.norm() + b.half.norm()));
    return b;
  }
  if (kind == 4) {
    b.half = a.half.cwiseMin(Eigen::Vector2d(1, 1)) * rng.uniform(0.01, 0.3);
    const double along = rng.uniform(-0.5, 0.5);
    const double across = rng.uniform(-0.5, 0.5);
    b.center = a.center + a.axis * along * a.half.x() + a.perp() * across * a.half.y();
    return b;
  }
  // Near touching along one of the four face normals, with a gap of either sign.
  const int axis = rng.integer(0, 3);
  const Eigen::Vector2d d = rng.sign() * (axis == 0   ? a.axis
                                          : axis == 1 ? a.perp()
                                          : axis == 2 ? b.axis
                                                      : b.perp());
  const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
  const Eigen::Vector2d lateral{-d.y(), d.x()};
  const double gap = rng.signedLogUniform(1e-9, 1.0);
  const double shift = rng.uniform(-0.5, 0.5);
  b.center = a.center + d * (reach + gap) +
             lateral * shift * std::min(a.half.minCoeff(), b.half.minCoeff());
  return b;
}

// A query box near the origin, far out (up to 1e7 m), axis-aligned (for exact touching), or
// extreme in size.
Obb2 queryBox(Random& rng) {
  switch (rng.integer(0, 3)) {
    case 0:
      return rng.box(rng.offset(0, 50), 0.1, 20.0);
    case 1:
      return rng.box(rng.farPoint(1e7), 0.1, 20.0);
    case 2: {
      const double far = rng.integer(0, 1) == 0 ? 0.0 : 4194304.0;  // 2^22: sums stay exact
      return {{far + dyadic(rng, -8, 8), far + dyadic(rng, -8, 8)},
              {1, 0},
              {dyadic(rng, 0.25, 10.0), dyadic(rng, 0.25, 10.0)}};
    }
    default:
      return rng.extremeBox(rng.offset(0, 1000));
  }
}

struct Batch {
  Obb2 a;
  std::vector<Obb2> boxes;
};

Batch randomBatch(Random& rng, int max_size) {
  Batch batch{queryBox(rng), {}};
  const int n = rng.integer(0, max_size);
  for (int i = 0; i < n; ++i) batch.boxes.push_back(boxFor(batch.a, rng));
  return batch;
}

struct Outputs {
  std::vector<std::uint8_t> hit;
  std::vector<double> sep, nx, ny;
};

Outputs runBatch(const Obb2& a, const Obb2Batch& many) {
  Outputs o{std::vector<std::uint8_t>(many.size(), 7), std::vector<double>(many.size()),
            std::vector<double>(many.size()), std::vector<double>(many.size())};
  overlapObb2Batch(a, many, o.hit);
  collideObb2Batch(a, many, o.sep, o.nx, o.ny);
  return o;
}

TEST(Obb2Batch, StoresTheBoxesExactly) {
  Random rng(11);
  std::vector<Obb2> boxes;
  for (int i = 0; i < 9; ++i) boxes.push_back(rng.box(rng.farPoint(1e7), 0.01, 100.0));
  const Obb2Batch batch(boxes);
  ASSERT_EQ(batch.size(), boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_EQ(batch.box(i).center, boxes[i].center);
    EXPECT_EQ(batch.box(i).axis, boxes[i].axis);
    EXPECT_EQ(batch.box(i).half, boxes[i].half);
  }
  EXPECT_GE(batch.memoryBytes(), boxes.size() * 6 * sizeof(double));
}

TEST(Obb2Batch, EqualsScalarBitForBitOnEveryPath) {
  testing::BatchPathGuard guard;
  Random rng(2024);
  const int batches = testing::scaledCount(4000);
  int pairs = 0, hits = 0;
  for (int k = 0; k < batches; ++k) {
    const Batch batch = randomBatch(rng, 67);
    const Obb2Batch many(batch.boxes);
    std::vector<Outputs> per_path;
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      per_path.push_back(runBatch(batch.a, many));
      const Outputs& o = per_path.back();
      for (std::size_t i = 0; i < batch.boxes.size(); ++i) {
        const Obb2& b = batch.boxes[i];
        const SatResult2 r = collideObb2(batch.a, b);
        ASSERT_EQ(o.hit[i], overlapObb2(batch.a, b) ? 1 : 0)
            << batchPathName(path) << " batch " << k << " box " << i;
        ASSERT_TRUE(sameBits(o.sep[i], r.separation) && sameBits(o.nx[i], r.normal.x()) &&
                    sameBits(o.ny[i], r.normal.y()))
            << batchPathName(path) << " batch " << k << " box " << i << ": sep " << o.sep[i]
            << " vs " << r.separation;
      }
    }
    for (std::size_t p = 1; p < per_path.size(); ++p) {
      ASSERT_EQ(per_path[p].hit, per_path[0].hit);
      for (std::size_t i = 0; i < batch.boxes.size(); ++i) {
        ASSERT_TRUE(sameBits(per_path[p].sep[i], per_path[0].sep[i]));
      }
    }
    pairs += static_cast<int>(batch.boxes.size());
    for (const std::uint8_t h : per_path[0].hit) hits += h;
  }
  // The mix must exercise both verdicts in earnest.
  EXPECT_GT(hits, pairs / 5);
  EXPECT_LT(hits, 4 * pairs / 5);
}

TEST(Obb2Batch, AgreesWithTheExactOracleOnEveryPath) {
  testing::BatchPathGuard guard;
  Random rng(77);
  const int batches = testing::scaledCount(600);
  int checked = 0, borderline = 0;
  double worst = 0.0;
  for (int k = 0; k < batches; ++k) {
    const Batch batch = randomBatch(rng, 40);
    const Obb2Batch many(batch.boxes);
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      const Outputs o = runBatch(batch.a, many);
      for (std::size_t i = 0; i < batch.boxes.size(); ++i) {
        const exact::ExactResult ex = exact::collideObb2(batch.a, batch.boxes[i]);
        const double err = std::abs(o.sep[i] - ex.separation);
        worst = std::max(worst, err);
        ASSERT_LE(err, testing::kSepTolerance) << batchPathName(path) << " batch " << k;
        if (std::abs(ex.separation) > testing::kHitTolerance) {
          ASSERT_EQ(o.hit[i] == 1, ex.hit) << batchPathName(path) << " batch " << k;
        } else {
          ++borderline;
        }
        // The normal realises the separation: B's support minus A's along it.
        const Eigen::Vector2d n{o.nx[i], o.ny[i]};
        ASSERT_NEAR(n.norm(), 1.0, 1e-12);
        const double gap =
            testing::signedGap(batch.a.corners(), batch.boxes[i].corners(), n, batch.a.center);
        ASSERT_NEAR(gap, o.sep[i], testing::kSepTolerance);
        ++checked;
      }
    }
  }
  EXPECT_GT(borderline, checked / 20) << "the cases must include near-touching pairs";
  std::printf("    %d pairs checked, %d borderline, max |sep - exact| = %.3g m\n", checked,
              borderline, worst);
}

TEST(Obb2Batch, EveryTailLengthMatchesScalar) {
  testing::BatchPathGuard guard;
  Random rng(5);
  const Obb2 a = rng.box({3, -2}, 1.0, 5.0);
  std::vector<Obb2> all;
  for (int i = 0; i < 13; ++i) all.push_back(boxFor(a, rng));
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    for (std::size_t n = 0; n <= all.size(); ++n) {
      const Obb2Batch many(std::span<const Obb2>(all.data(), n));
      const Outputs o = runBatch(a, many);
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(o.hit[i], overlapObb2(a, all[i]) ? 1 : 0) << n << " " << i;
        EXPECT_TRUE(sameBits(o.sep[i], collideObb2(a, all[i]).separation)) << n << " " << i;
      }
    }
  }
}

TEST(Obb2Batch, TouchingCountsAsHitFarFromTheOrigin) {
  testing::BatchPathGuard guard;
  const Eigen::Vector2d far{4194304.0, -4194304.0};
  const Obb2 a{far, {1, 0}, {2.25, 1.0}};
  // Sharing an edge, sharing a corner, a hair apart, and turned 90 degrees sharing an edge.
  const std::vector<Obb2> boxes{{far + Eigen::Vector2d(4.5, 0.5), {1, 0}, {2.25, 1.0}},
                                {far + Eigen::Vector2d(4.5, 2.0), {1, 0}, {2.25, 1.0}},
                                {far + Eigen::Vector2d(4.5 + 0x1p-20, 0), {1, 0}, {2.25, 1.0}},
                                {far + Eigen::Vector2d(3.25, 0.0), {0, 1}, {2.0, 1.0}}};
  const Obb2Batch many(boxes);
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    const Outputs o = runBatch(a, many);
    EXPECT_EQ(o.hit, (std::vector<std::uint8_t>{1, 1, 0, 1})) << batchPathName(path);
    EXPECT_EQ(o.sep[0], 0.0);
    EXPECT_EQ(o.sep[2], 0x1p-20);
    EXPECT_EQ(o.nx[2], 1.0);
    EXPECT_EQ(o.ny[2], 0.0);
  }
}

// Car-sized pairs as the benchmark draws them: B within `reach` of A, any heading.
std::vector<Obb2> carsAround(const Obb2& a, Random& rng, int n, double reach) {
  std::vector<Obb2> boxes;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d direction = rng.direction();
    const Eigen::Vector2d c = a.center + direction * reach * std::sqrt(rng.uniform(0, 1));
    boxes.push_back({c, rng.direction(), {rng.uniform(1.75, 2.75), rng.uniform(0.8, 1.1)}});
  }
  return boxes;
}

TEST(Obb2Batch, FloatFilterDecidesAlmostEveryRandomPair) {
  testing::BatchPathGuard guard;
  Random rng(31);
  std::size_t pairs = 0, sent_on = 0;
  for (int k = 0; k < testing::scaledCount(200); ++k) {
    const Obb2 a{rng.farPoint(1e7), rng.direction(), {2.25, 0.9}};
    const std::vector<Obb2> boxes = carsAround(a, rng, 500, 6.0);
    const Obb2Batch many(boxes);
    ASSERT_TRUE(many.filterUsable());
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      std::vector<std::uint8_t> hit(boxes.size());
      const std::size_t undecided = overlapObb2Batch(a, many, hit);
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        ASSERT_EQ(hit[i], overlapObb2(a, boxes[i]) ? 1 : 0) << batchPathName(path) << " " << i;
      }
      if (path == BatchPath::kPortable) {
        EXPECT_EQ(undecided, 0u) << "the portable path has no filter";
      } else {
        pairs += boxes.size();
        sent_on += undecided;
      }
    }
  }
  // Only pairs within about 1e-4 m of touching are left to the double kernel: a handful in 1e5.
  EXPECT_LE(sent_on * 1000, pairs) << sent_on << " of " << pairs;
  std::printf("    %zu of %zu pairs sent to the double kernel\n", sent_on, pairs);
}

// Pairs a hair from touching on a random axis, where the filter must hand over to double: gaps
// of either sign from 1e-12 m to 1 mm, boxes from 1 cm to 100 m, the query near the batch or far
// from its reference point, batches spread over up to 1e4 m, 1e7 m from the origin.
TEST(Obb2Batch, NearTouchingPairsAtTheFilterMarginMatchScalar) {
  testing::BatchPathGuard guard;
  Random rng(4242);
  std::size_t pairs = 0, sent_on = 0;
  for (int k = 0; k < testing::scaledCount(1500); ++k) {
    const Eigen::Vector2d origin =
        rng.integer(0, 1) == 0 ? Eigen::Vector2d::Zero() : rng.farPoint(1e7);
    const Obb2 a = rng.integer(0, 1) == 0 ? rng.extremeBox(origin) : rng.box(origin, 0.01, 100.0);
    std::vector<Obb2> boxes;
    // Now and then a batch long enough that the boxes left open fill the buffer in which the
    // sixteen-lane path collects them (runFilteredByBox) before its end.
    const int n = rng.integer(0, 9) == 0 ? rng.integer(100, 400) : rng.integer(1, 40);
    for (int i = 0; i < n; ++i) {
      Obb2 b = rng.integer(0, 2) == 0 ? rng.extremeBox({0, 0}) : rng.box({0, 0}, 0.01, 100.0);
      const int axis = rng.integer(0, 3);
      const Eigen::Vector2d d = rng.sign() * (axis == 0   ? a.axis
                                              : axis == 1 ? a.perp()
                                              : axis == 2 ? b.axis
                                                          : b.perp());
      const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
      const Eigen::Vector2d lateral{-d.y(), d.x()};
      const double gap = rng.signedLogUniform(1e-12, 1e-3);
      const double shift = rng.uniform(-0.4, 0.4);
      b.center = a.center + d * (reach + gap) +
                 lateral * shift * std::min(a.half.minCoeff(), b.half.minCoeff());
      boxes.push_back(b);
    }
    // Now and then a far box widens the batch, which moves its reference point away from A.
    if (rng.integer(0, 3) == 0) boxes.push_back(rng.box(a.center + rng.farPoint(1e4), 1.0, 5.0));
    const Obb2Batch many(boxes);
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      std::vector<std::uint8_t> hit(boxes.size());
      const std::size_t undecided = overlapObb2Batch(a, many, hit);
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        ASSERT_EQ(hit[i], overlapObb2(a, boxes[i]) ? 1 : 0)
            << batchPathName(path) << " batch " << k << " box " << i;
      }
      if (path != BatchPath::kPortable) {
        pairs += boxes.size();
        sent_on += undecided;
      }
    }
  }
  if (pairs > 0) {
    // Gaps below the margin must reach the double kernel, and wider ones must not all do so.
    EXPECT_GT(sent_on, pairs / 10);
    EXPECT_LT(sent_on, pairs * 9 / 10);
  }
}

TEST(Obb2Batch, TinyHugeAndOutOfRangeBoxesMatchScalar) {
  testing::BatchPathGuard guard;
  Random rng(8);
  // Half extents down to 1e-40 m (float underflows), coordinates up to 1e25 m (past the filter's
  // 2^60 m range: that batch and that query go to the double kernel whole).
  const Obb2 small_a{{3.0, -1.0}, rng.direction(), {1e-40, 3e-41}};
  const Obb2 far_a{{1e25, -2e24}, rng.direction(), {2.0, 1.0}};
  const Obb2 plain_a{{0.5, 0.25}, rng.direction(), {2.0, 1.0}};
  std::vector<Obb2> tiny{small_a,
                         {{3.0, -1.0}, rng.direction(), {2e-40, 1e-45}},
                         {{3.0 + 1e-39, -1.0}, rng.direction(), {1e-40, 1e-40}},
                         {{3.0, -1.0 + 1e-30}, rng.direction(), {1e-40, 1e-40}}};
  for (int i = 0; i < 20; ++i) tiny.push_back(rng.box(plain_a.center + rng.direction(), 1e-6, 3.0));
  std::vector<Obb2> huge = tiny;
  huge.push_back({{1e25, -2e24}, rng.direction(), {3.0, 1.0}});
  const Obb2Batch tiny_batch(tiny), huge_batch(huge);
  EXPECT_TRUE(tiny_batch.filterUsable());
  EXPECT_FALSE(huge_batch.filterUsable());
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    for (const Obb2* a : {&small_a, &far_a, &plain_a}) {
      for (const auto* batch : {&tiny, &huge}) {
        const Obb2Batch& many = batch == &tiny ? tiny_batch : huge_batch;
        std::vector<std::uint8_t> hit(batch->size());
        const std::size_t undecided = overlapObb2Batch(*a, many, hit);
        for (std::size_t i = 0; i < batch->size(); ++i) {
          ASSERT_EQ(hit[i], overlapObb2(*a, (*batch)[i]) ? 1 : 0) << batchPathName(path) << i;
        }
        const bool whole = path != BatchPath::kPortable && (a == &far_a || batch == &huge);
        if (whole) {
          EXPECT_EQ(undecided, batch->size()) << batchPathName(path);
        }
      }
    }
  }
}

TEST(BatchPath, TheEnvironmentNamesEachPathAndFallsBackToANarrowerOne) {
  const std::vector<BatchPath> paths = testing::availableBatchPaths();
  const BatchPath widest = paths.back();
  EXPECT_EQ(batchPathNamed(nullptr), widest);
  EXPECT_EQ(batchPathNamed("fastest"), widest);
  EXPECT_EQ(batchPathNamed("portable"), BatchPath::kPortable);
  EXPECT_EQ(batchPathNamed("avx2"),
            batchPathAvailable(BatchPath::kAvx2) ? BatchPath::kAvx2 : BatchPath::kPortable);
  EXPECT_EQ(batchPathNamed("avx512"), widest);
  for (const BatchPath path : paths) EXPECT_EQ(batchPathNamed(batchPathName(path)), path);
}

TEST(BatchPath, ForcingTheFallbackSticksAndAvx2IsUsedWhenAvailable) {
  testing::BatchPathGuard guard;
  setBatchPath(BatchPath::kPortable);
  EXPECT_EQ(batchPath(), BatchPath::kPortable);
  EXPECT_TRUE(batchPathAvailable(BatchPath::kPortable));
  EXPECT_STREQ(batchPathName(BatchPath::kPortable), "portable");
  EXPECT_STREQ(batchPathName(BatchPath::kAvx2), "avx2");
  EXPECT_STREQ(batchPathName(BatchPath::kAvx512), "avx512");
  // The wider path is only there with the narrower one (it keeps the AVX2 3D kernels).
  if (batchPathAvailable(BatchPath::kAvx512)) {
    EXPECT_TRUE(batchPathAvailable(BatchPath::kAvx2));
  }
#if defined(__x86_64__)
  // This project's CPUs (and CI's) have AVX2; a build without the AVX2 file says so.
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    std::printf("    AVX2 path %s\n",
                batchPathAvailable(BatchPath::kAvx2) ? "available" : "not built");
  }
  if (__builtin_cpu_supports("avx512f")) {
    std::printf("    AVX-512 path %s\n",
                batchPathAvailable(BatchPath::kAvx512) ? "available" : "not built");
  }
#endif
}

}  // namespace
}  // namespace cardemo
