/// Batch 3D SAT (one box against many) against the exact oracle, the scalar collideObb3, and
/// itself on both dispatch paths, over the seeded classes of random_cases3.hpp.

#include "lab/kernels/obb3_batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "geometry/batch_path.hpp"
#include "tests/geometry/random_cases3.hpp"
#include "tests/support/batch_paths.hpp"
#include "tests/support/random_class.hpp"

namespace cardemo {
namespace {

using test3::Pair3;

using testing::ClassStats;
using testing::Failures;
using testing::kHitTolerance;
using testing::kSepTolerance;
// Batch and scalar are both within ~1e-14 m of the truth here; 1e-9 m leaves room for sizes and
// offsets up to 1e7 m while still catching any wrong axis or sign.
constexpr double kScalarTolerance = 1e-9;

using testing::sameBits;

// The generated B, plus copies moved to other gaps along candidate axes of the pair, so that a
// whole batch shares the pair's rotation relation (near-parallel, exactly parallel, ...).
std::vector<Obb3> batchFor(const Pair3& p, std::mt19937_64& rng) {
  std::vector<Obb3> boxes{p.b};
  const int extra = static_cast<int>(rng() % 7);
  for (int k = 0; k < extra; ++k) {
    Obb3 b = p.b;
    Eigen::Vector3d n = test3::candidateAxis(p.a, p.b, static_cast<int>(rng() % 15));
    if (n.isZero()) n = test3::randomUnit(rng);
    test3::placeAtRandomGap(rng, p.a, b, n);
    boxes.push_back(b);
  }
  return boxes;
}

// Separation and hit of `a` against every box of `many` on every batch path this CPU has
// (testing::availableBatchPaths order); the caller's BatchPathGuard restores the path.
struct PathResults {
  std::vector<std::vector<double>> seps;  ///< Per path, per box.
  std::vector<std::vector<std::uint8_t>>
      hits;  ///< Per path, per box (7 where nothing was written).
};

PathResults onEveryPath(const Obb3& a, const Obb3Batch& many) {
  PathResults out;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    out.seps.emplace_back(many.size());
    out.hits.emplace_back(many.size(), 7);
    separationObb3Batch(a, many, out.seps.back());
    overlapObb3Batch(a, many, out.hits.back());
  }
  return out;
}

// Each case is a generated pair widened to a batch (batchFor), checked box by box on every path
// against the oracle and the scalar collideObb3; the class's stats count boxes, not cases.
void runClass(const char* name, std::uint64_t seed,
              const std::function<Pair3(std::mt19937_64&)>& gen, int count = 1500,
              bool strict_hit = false) {
  testing::BatchPathGuard guard;
  double worst_scalar = 0.0;
  const ClassStats s = testing::runRandomClass(
      name, seed, count, [&](std::mt19937_64& rng, int k, Failures& f, ClassStats& t) {
        const Pair3 p = gen(rng);
        const std::vector<Obb3> boxes = batchFor(p, rng);
        const PathResults on = onEveryPath(p.a, Obb3Batch(boxes));
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          const double sep = on.seps[0][i];
          const bool hit = on.hits[0][i] == 1;
          // Messages are built only for a failure: this runs for every box of every case.
          const auto fail = [&](const char* what) {
            f.fail(k,
                   std::string(what) + " box " + std::to_string(i) + " sep " + std::to_string(sep));
          };
          for (std::size_t q = 1; q < on.seps.size(); ++q) {
            if (!sameBits(on.seps[q][i], sep) || on.hits[q][i] != on.hits[0][i])
              fail("paths differ");
          }
          if (hit != (sep <= 0.0)) fail("overlap disagrees with sep");
          const exact::ExactResult ex = exact::collideObb3(p.a, boxes[i]);
          const SatResult3 scalar = collideObb3(p.a, boxes[i]);
          const double err = std::abs(sep - ex.separation);
          const double diff = std::abs(sep - scalar.separation);
          t.max_error = std::max(t.max_error, err);
          worst_scalar = std::max(worst_scalar, diff);
          if (!(err <= kSepTolerance)) fail("sep off the oracle");
          if (!(diff <= kScalarTolerance)) fail("sep off the scalar");
          if ((strict_hit || std::abs(ex.separation) > kHitTolerance) && hit != ex.hit) {
            fail("hit wrong");
          }
          t.tally(ex.hit, ex.separation);
        }
      });
  std::printf("[ %s ] worst |sep - scalar| %.3g m\n", name, worst_scalar);
  EXPECT_GT(s.exact_hits, 0) << name;
}

TEST(Obb3Batch, StoresTheBoxesExactly) {
  std::mt19937_64 rng(3);
  std::vector<Obb3> boxes;
  for (int i = 0; i < 6; ++i) {
    boxes.push_back(test3::randomBox(rng));
  }
  const Obb3Batch batch(boxes);
  ASSERT_EQ(batch.size(), boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_EQ(batch.box(i).center, boxes[i].center);
    EXPECT_EQ(batch.box(i).rotation(), boxes[i].rotation());
    EXPECT_EQ(batch.box(i).half, boxes[i].half);
  }
  EXPECT_GE(batch.memoryBytes(), boxes.size() * 15 * sizeof(double));
}

TEST(Obb3BatchRandom, GapsBothSidesOfTouching) {
  runClass("gaps", 0xba7c0001, test3::gapPair);
}

TEST(Obb3BatchRandom, FarFromOrigin) {
  runClass("far", 0xba7c0002, test3::farPair);
}

TEST(Obb3BatchRandom, ExtremeSizesAndAspects) {
  runClass("sizes", 0xba7c0003, test3::sizePair);
}

TEST(Obb3BatchRandom, NearParallelEdges) {
  runClass("near-parallel", 0xba7c0004,
           [](std::mt19937_64& rng) { return test3::nearParallelPair(rng); });
}

TEST(Obb3BatchRandom, ExactlyCoincidentAndParallel) {
  runClass("coincident", 0xba7c0005, test3::coincidentPair, 1000);
  runClass("parallel", 0xba7c0006, test3::parallelPair);
}

TEST(Obb3BatchRandom, Containment) {
  runClass("containment", 0xba7c0007, test3::containmentPair);
}

TEST(Obb3BatchRandom, ExactTouchingIsAHit) {
  // batchFor only adds moved copies at random gaps; the generated B itself touches exactly.
  runClass("touching", 0xba7c0008, test3::touchingPair, 1500, false);
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0xba7c0009);
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    for (int k = 0; k < 500; ++k) {
      const Pair3 p = test3::touchingPair(rng);
      const std::vector<Obb3> one{p.b};
      const Obb3Batch many(one);
      double sep = 1.0;
      std::uint8_t hit = 0;
      separationObb3Batch(p.a, many, std::span<double>(&sep, 1));
      overlapObb3Batch(p.a, many, std::span<std::uint8_t>(&hit, 1));
      EXPECT_EQ(sep, 0.0) << batchPathName(path);
      EXPECT_EQ(hit, 1) << batchPathName(path);
    }
  }
}

// The kernels' fast filter works in A's frame and hands near-touching pairs and edges within about
// 1.4 degrees of parallel to the accurate kernel. Angles around that threshold, and full batches of
// randomly rotated boxes (every lane group taking the fast path), on every path: the verdict is
// the exact one whenever |sep| > 1e-6 m, and sep is within 2^-39 of the pair's scale of the scalar.
TEST(Obb3BatchRandom, FastFilterAgreesAroundItsThresholds) {
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0xba7c000a);
  const int n = test3::scaledCount(300);
  int pairs = 0, hits = 0;
  double worst_relative = 0.0;
  for (int k = 0; k < n; ++k) {
    const bool angles = k % 2 == 0;
    const Pair3 first = angles ? test3::nearParallelPair(rng, 1e-3, 0.2) : test3::gapPair(rng);
    std::vector<Obb3> boxes{first.b};
    const int count = 4 + static_cast<int>(rng() % 29);
    while (static_cast<int>(boxes.size()) < count) {
      Obb3 b = test3::randomBoxAt(rng, {0, 0, 0});
      if (angles) {
        // Another near-parallel pair's relative rotation, carried over to this A.
        const Pair3 other = test3::nearParallelPair(rng, 1e-3, 0.2);
        const Eigen::Matrix3d relative = other.a.rotation().transpose() * other.b.rotation();
        b = Obb3::fromQuaternion({0, 0, 0}, Eigen::Quaterniond(first.a.rotation() * relative),
                                 2.0 * other.b.half);
      }
      const double reach = first.a.half.norm() + b.half.norm();
      b.center = first.a.center + test3::randomOffset(rng, 0.0, 1.5 * reach);
      boxes.push_back(b);
    }
    const PathResults on = onEveryPath(first.a, Obb3Batch(boxes));
    const auto& seps = on.seps;
    const auto& hit_sets = on.hits;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double sep = seps[0][i];
      for (std::size_t q = 1; q < seps.size(); ++q) {
        ASSERT_TRUE(sameBits(seps[q][i], sep)) << "case " << k << " box " << i;
        ASSERT_EQ(hit_sets[q][i], hit_sets[0][i]) << "case " << k << " box " << i;
      }
      ASSERT_EQ(hit_sets[0][i] == 1, sep <= 0.0) << "case " << k << " box " << i;
      const Eigen::Vector3d d = boxes[i].center - first.a.center;
      const double scale = d.cwiseAbs().sum() + first.a.half.sum() + boxes[i].half.sum();
      const SatResult3 scalar = collideObb3(first.a, boxes[i]);
      worst_relative = std::max(worst_relative, std::abs(sep - scalar.separation) / scale);
      ASSERT_LE(std::abs(sep - scalar.separation), 0x1p-39 * scale) << "case " << k << " box " << i;
      const exact::ExactResult ex = exact::collideObb3(first.a, boxes[i]);
      ASSERT_LE(std::abs(sep - ex.separation), kSepTolerance) << "case " << k << " box " << i;
      if (std::abs(ex.separation) > kHitTolerance) {
        ASSERT_EQ(hit_sets[0][i] == 1, ex.hit) << "case " << k << " box " << i;
      }
      ++pairs;
      hits += ex.hit ? 1 : 0;
    }
  }
  std::printf("    [filter] %d pairs, %d exact hits, worst |sep - scalar| / scale %.3g\n", pairs,
              hits, worst_relative);
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, pairs);
}

// Boxes of car to lorry size at random headings and tilts within `reach` metres of A.
std::vector<Obb3> boxesAround(const Obb3& a, std::mt19937_64& rng, int n, double reach) {
  std::vector<Obb3> boxes;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d size{test3::uniform(rng, 3.5, 12.0), test3::uniform(rng, 1.6, 2.6),
                               test3::uniform(rng, 1.2, 4.0)};
    const Eigen::Quaterniond q = test3::randomRotation(rng);
    boxes.push_back(Obb3::fromQuaternion(a.center + test3::randomOffset(rng, 0.0, reach), q, size));
  }
  return boxes;
}

// Every verdict of overlapObb3Batch on every SIMD path (float pre-filter, then the double kernel)
// equals the portable path's (the double kernel alone, whose bits every path shares), and the
// scalar overlapObb3's wherever the pair is not within 1e-9 m of touching (the two order their
// operations differently, so they agree to rounding). Returns the pairs the float pre-filter left
// to the double kernel (summed over the SIMD paths) and counts the pairs those paths saw in
// `pairs`.
std::size_t expectDoubleKernelVerdicts(const Obb3& a, const std::vector<Obb3>& boxes,
                                       const Obb3Batch& many, std::size_t& pairs,
                                       const char* what) {
  setBatchPath(BatchPath::kPortable);
  std::vector<std::uint8_t> reference(boxes.size(), 7);
  EXPECT_EQ(overlapObb3Batch(a, many, reference), 0u) << "the portable path has no pre-filter";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (std::abs(collideObb3(a, boxes[i]).separation) > 1e-9) {
      EXPECT_EQ(reference[i], overlapObb3(a, boxes[i]) ? 1 : 0) << what << " box " << i;
    }
  }
  // The separation kernel's own A-frame filter leaves the boxes nearest touching to its accurate
  // kernel, one by one on the wide paths: the separations must still be the portable path's bits.
  std::vector<double> reference_sep(boxes.size());
  separationObb3Batch(a, many, reference_sep);
  std::size_t sent_on = 0;
  for (const BatchPath path : testing::availableBatchPaths()) {
    if (path == BatchPath::kPortable) continue;
    setBatchPath(path);
    std::vector<std::uint8_t> hit(boxes.size(), 7);
    sent_on += overlapObb3Batch(a, many, hit);
    std::vector<double> sep(boxes.size());
    separationObb3Batch(a, many, sep);
    pairs += boxes.size();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      EXPECT_EQ(hit[i], reference[i]) << what << " " << batchPathName(path) << " box " << i;
      EXPECT_TRUE(sameBits(sep[i], reference_sep[i]))
          << what << " " << batchPathName(path) << " box " << i << ": " << sep[i] << " against "
          << reference_sep[i];
    }
  }
  return sent_on;
}

TEST(Obb3Batch, FloatFilterDecidesAlmostEveryRandomPair) {
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0x3f17e5);
  std::size_t pairs = 0, sent_on = 0;
  for (int k = 0; k < test3::scaledCount(100); ++k) {
    const Eigen::Vector3d far{test3::farCoordinate(rng), test3::farCoordinate(rng),
                              test3::farCoordinate(rng)};
    const Obb3 a = Obb3::fromQuaternion(far, test3::randomRotation(rng), {4.5, 1.8, 1.5});
    const std::vector<Obb3> boxes = boxesAround(a, rng, 400, 12.0);
    const Obb3Batch many(boxes);
    ASSERT_TRUE(many.filterUsable());
    sent_on += expectDoubleKernelVerdicts(a, boxes, many, pairs, "random");
  }
  // Only pairs within about 1e-4 m of touching go on (one by one, not with their lane group).
  if (pairs > 0) {
    EXPECT_LE(sent_on * 50, pairs) << sent_on << " of " << pairs;
  }
  std::printf("    %zu of %zu pairs sent to the double kernel\n", sent_on, pairs);
}

// Pairs a hair from touching along one of their fifteen axes (or a random direction), where the
// filter must hand over to double: gaps of either sign from 1e-12 m to 1 cm, boxes from 1 cm to
// 100 m, near the origin or 1e6-1e7 m out, the batch sometimes widened by a box 1e4 m away, which
// moves its reference point away from A.
TEST(Obb3Batch, NearTouchingPairsAtTheFilterMarginMatchTheDoubleKernel) {
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0x3f17e6);
  std::size_t pairs = 0, sent_on = 0;
  for (int k = 0; k < test3::scaledCount(600); ++k) {
    const Obb3 a = rng() % 2 == 0 ? test3::randomBoxAt(rng, {0, 0, 0}) : test3::randomBox(rng);
    std::vector<Obb3> boxes;
    // Now and then a batch long enough that the open boxes fill the filters' buffers
    // (runFilteredByBox, runSeparation3) before its end.
    const int n =
        rng() % 10 == 0 ? 100 + static_cast<int>(rng() % 300) : 1 + static_cast<int>(rng() % 40);
    for (int i = 0; i < n; ++i) {
      Obb3 b = test3::randomBoxAt(rng, {0, 0, 0});
      const int axis = static_cast<int>(rng() % 16);
      Eigen::Vector3d u = axis < 15 ? test3::candidateAxis(a, b, axis) : test3::randomUnit(rng);
      if (u.isZero()) u = test3::randomUnit(rng);
      const double sign = test3::randomSign(rng);
      test3::placeAtGap(a, b, sign * u,
                        test3::randomSign(rng) * test3::logUniform(rng, 1e-12, 1e-2));
      boxes.push_back(b);
    }
    if (rng() % 4 == 0) {
      boxes.push_back(test3::randomBoxAt(rng, a.center + test3::randomOffset(rng, 1e3, 1e4)));
    }
    const Obb3Batch many(boxes);
    sent_on += expectDoubleKernelVerdicts(a, boxes, many, pairs, "near touching");
  }
  if (pairs > 0) {
    // Gaps below the margin must reach the double kernel, and wider ones must not all do so.
    EXPECT_GT(sent_on, pairs / 10) << sent_on << " of " << pairs;
    EXPECT_LT(sent_on, pairs * 9 / 10) << sent_on << " of " << pairs;
  }
}

// A batch in which every box lies a hair (1e-13 to 1e-11 m) beyond one of A's faces: the separation
// kernel's filter leaves each to its accurate kernel, so the buffer of open boxes fills and is
// emptied many times before the end of the batch. Every path gives the portable path's bits.
TEST(Obb3Batch, SeparationsOfAllOpenBoxesFillTheBufferAndMatchThePortablePath) {
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0x3f17e8);
  const Obb3 a = test3::randomBoxAt(rng, {1e6, -2e5, 3e4});
  std::vector<Obb3> boxes;
  for (int i = 0; i < 1000; ++i) {
    Obb3 b = test3::randomBoxAt(rng, {0, 0, 0});
    const Eigen::Vector3d u =
        test3::randomSign(rng) * a.rotation().col(static_cast<int>(rng() % 3));
    test3::placeAtGap(a, b, u, test3::logUniform(rng, 1e-13, 1e-11));
    boxes.push_back(b);
  }
  const Obb3Batch many(boxes);
  setBatchPath(BatchPath::kPortable);
  std::vector<double> reference(boxes.size());
  separationObb3Batch(a, many, reference);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    ASSERT_NEAR(reference[i], exact::collideObb3(a, boxes[i]).separation, kSepTolerance) << i;
  }
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    std::vector<double> sep(boxes.size(), 7.0);
    separationObb3Batch(a, many, sep);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      EXPECT_TRUE(sameBits(sep[i], reference[i]))
          << batchPathName(path) << " box " << i << ": " << sep[i] << " against " << reference[i];
    }
  }
}

// Half extents down to 1e-40 m (float underflows), centres past the filter's 2^60 m range (that
// batch, or that query, goes to the double kernel whole), and a query whose frame is too far from
// orthonormal for the A-frame gaps (the filter turns itself off).
TEST(Obb3Batch, TinyHugeSkewedAndOutOfRangeBoxesMatchTheDoubleKernel) {
  testing::BatchPathGuard guard;
  std::mt19937_64 rng(0x3f17e7);
  const Eigen::Quaterniond q = test3::randomRotation(rng);
  const Obb3 small_a = Obb3::fromQuaternion({3.0, -1.0, 2.0}, q, {2e-40, 6e-41, 1e-40});
  const Obb3 far_a = Obb3::fromQuaternion({1e25, -2e24, 3e24}, q, {2.0, 1.0, 1.0});
  const Obb3 plain_a = Obb3::fromQuaternion({0.5, 0.25, -0.5}, q, {4.0, 2.0, 1.5});
  const Obb3 skewed_a = [&plain_a] {
    Obb3 b = plain_a;
    Eigen::Matrix3d skew = plain_a.rotation();
    skew(0, 1) += 1e-8;  // a frame defect of about 1e-8, beyond the filter's 2^-30
    b.setRotation(skew);
    return b;
  }();
  std::vector<Obb3> tiny{
      small_a,
      Obb3::fromQuaternion({3.0, -1.0, 2.0}, test3::randomRotation(rng), {4e-40, 2e-45, 1e-40}),
      Obb3::fromQuaternion({3.0 + 1e-39, -1.0, 2.0}, q, {2e-40, 2e-40, 2e-40})};
  for (int i = 0; i < 40; ++i) {
    tiny.push_back(test3::randomBoxAt(rng, plain_a.center + test3::randomOffset(rng, 0.0, 6.0)));
  }
  std::vector<Obb3> huge = tiny;
  huge.push_back(Obb3::fromQuaternion({1e25, -2e24, 3e24}, q, {3.0, 1.0, 1.0}));
  const Obb3Batch tiny_batch(tiny), huge_batch(huge);
  EXPECT_TRUE(tiny_batch.filterUsable());
  EXPECT_FALSE(huge_batch.filterUsable());
  for (const Obb3* a : {&small_a, &far_a, &plain_a, &skewed_a}) {
    for (const auto* batch : {&tiny, &huge}) {
      const Obb3Batch& many = batch == &tiny ? tiny_batch : huge_batch;
      std::size_t pairs = 0;
      const std::size_t sent_on = expectDoubleKernelVerdicts(*a, *batch, many, pairs, "extreme");
      if (a == &far_a || a == &skewed_a || batch == &huge) {
        EXPECT_EQ(sent_on, pairs) << "the filter cannot run here, so every pair goes on";
      }
    }
  }
}

// Crossed beams near-parallel to 1e-15 rad far from the origin: only an edge axis separates them.
TEST(Obb3Batch, CrossedBeamsSeparatedByAnEdgeAxisOnEveryPath) {
  testing::BatchPathGuard guard;
  for (const double angle : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3}) {
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()));
    const Obb3 a =
        Obb3::fromQuaternion({1e7, -3e6, 2e5}, Eigen::Quaterniond::Identity(), {100.0, 0.5, 0.5});
    const Obb3 shape = Obb3::fromQuaternion({0, 0, 0}, tilt, {100.0, 0.5, 0.5});
    const Eigen::Vector3d u = a.rotation().col(0).cross(shape.rotation().col(0)).normalized();
    std::vector<Obb3> boxes;
    for (const double gap : {-1e-3, -1e-7, 1e-7, 1e-3, 2e-6}) {
      Obb3 b = shape;
      test3::placeAtGap(a, b, u, gap);
      boxes.push_back(b);
    }
    const Obb3Batch many(boxes);
    for (const BatchPath path : testing::availableBatchPaths()) {
      setBatchPath(path);
      std::vector<double> sep(boxes.size());
      std::vector<std::uint8_t> hit(boxes.size());
      separationObb3Batch(a, many, sep);
      overlapObb3Batch(a, many, hit);
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const exact::ExactResult ex = exact::collideObb3(a, boxes[i]);
        EXPECT_NEAR(sep[i], ex.separation, kSepTolerance) << angle << " " << i;
        EXPECT_EQ(hit[i] == 1, ex.hit) << angle << " " << i << " " << batchPathName(path);
      }
    }
  }
}

}  // namespace
}  // namespace cardemo
