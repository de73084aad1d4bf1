/// The batched manifold against manifoldObb2, bit for bit on every dispatch path, over seeded
/// random pairs (near the origin and 1e7 m out, every tail length) and named edge cases.

#include "lab/kernels/manifold2_batch.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "geometry/batch_path.hpp"
#include "manifold_pairs.hpp"
#include "tests/geometry/random_cases2.hpp"
#include "tests/support/batch_paths.hpp"
#include "tests/support/random_class.hpp"

namespace cardemo {
namespace {

using testing::Failures;
using testing::Random;
using testing::sameBits;

bool samePoint(const ContactPoint2& p, const ContactPoint2& q) {
  return sameBits(p.point.x(), q.point.x()) && sameBits(p.point.y(), q.point.y()) &&
         sameBits(p.separation, q.separation) && p.feature == q.feature;
}

// Every field, bit for bit (points past the count are default in both).
bool sameManifold(const Manifold2& m, const Manifold2& s) {
  return m.count == s.count && m.reference_face == s.reference_face &&
         sameBits(m.normal.x(), s.normal.x()) && sameBits(m.normal.y(), s.normal.y()) &&
         samePoint(m.points[0], s.points[0]) && samePoint(m.points[1], s.points[1]);
}

std::string describe(const Manifold2& m) {
  std::string out = "count " + std::to_string(m.count) + " face " +
                    std::to_string(m.reference_face) + " normal (" + std::to_string(m.normal.x()) +
                    ", " + std::to_string(m.normal.y()) + ")";
  for (int k = 0; k < m.count; ++k) {
    const ContactPoint2& p = m.points[static_cast<std::size_t>(k)];
    out += " [" + std::to_string(p.point.x()) + ", " + std::to_string(p.point.y()) + " sep " +
           std::to_string(p.separation) + " feature " + std::to_string(p.feature) + "]";
  }
  return out;
}

// Runs the batch on every path and checks each pair against manifoldObb2.
void checkPairs(const std::vector<Obb2>& a, const std::vector<Obb2>& b,
                const ManifoldSettings& settings, Failures& f, int& index) {
  testing::BatchPathGuard guard;
  const Obb2Batch batch_a(a), batch_b(b);
  Manifold2Batch out;
  for (const BatchPath path : testing::availableBatchPaths()) {
    setBatchPath(path);
    manifoldObb2Batch(batch_a, batch_b, out, settings);
    EXPECT_EQ(out.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Manifold2 scalar = manifoldObb2(a[i], b[i], settings);
      const Manifold2 batched = out.manifold(i);
      f.check(
          sameManifold(batched, scalar), index + static_cast<int>(i),
          std::string(batchPathName(path)) + ": " + describe(batched) + " vs " + describe(scalar));
    }
  }
  index += static_cast<int>(a.size());
}

struct Coverage {
  std::array<int, 3> counts{};  // manifolds with 0, 1, 2 points
  std::array<int, 8> faces{};   // reference faces
};

void runRandom(std::uint64_t seed, double offset, Failures& f, Coverage& seen) {
  Random rng(seed);
  const ManifoldSettings settings[3] = {{}, {0.0, 1.0, 0.0}, {0.05, 0.95, 0.002}};
  const int batches = testing::scaledCount(3000);
  int index = 0;
  for (int k = 0; k < batches; ++k) {
    // Every length from 0 to 67, so every tail of a lane group is met.
    const int n = k % 68;
    std::vector<Obb2> a, b;
    for (int i = 0; i < n; ++i) {
      const auto [box_a, box_b] = testing::manifoldPair(rng, offset, i);
      a.push_back(box_a);
      b.push_back(box_b);
    }
    const ManifoldSettings& s = settings[k % 3];
    checkPairs(a, b, s, f, index);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Manifold2 m = manifoldObb2(a[i], b[i], s);
      ++seen.counts[static_cast<std::size_t>(m.count)];
      if (m.reference_face >= 0) ++seen.faces[static_cast<std::size_t>(m.reference_face)];
    }
  }
}

TEST(Manifold2Batch, EqualsManifoldObb2BitForBitOnEveryPath) {
  Failures f;
  Coverage seen;
  runRandom(4101, 100.0, f, seen);
  EXPECT_EQ(f.count(), 0) << f.report();
  // The mix reaches every outcome: no contact, one and two points, and each of the eight faces.
  for (const int c : seen.counts) EXPECT_GT(c, testing::scaledCount(100));
  for (const int c : seen.faces) EXPECT_GT(c, testing::scaledCount(100));
}

TEST(Manifold2Batch, EqualsManifoldObb2FarFromTheOrigin) {
  Failures f;
  Coverage seen;
  runRandom(4102, 1e7, f, seen);
  EXPECT_EQ(f.count(), 0) << f.report();
  EXPECT_GT(seen.counts[2], testing::scaledCount(100));
}

TEST(Manifold2Batch, NamedCasesMatchTheScalarFunction) {
  const Obb2 unit{{0, 0}, {1, 0}, {1, 1}};
  const Eigen::Vector2d diagonal(std::sqrt(0.5), std::sqrt(0.5));
  const std::vector<std::pair<Obb2, Obb2>> cases = {
      {unit, unit},                              // identical: every face ties
      {unit, {{2, 0}, {1, 0}, {1, 1}}},          // face to face, exactly touching
      {unit, {{2, 2}, {1, 0}, {1, 1}}},          // corner to corner, exactly touching
      {unit, {{1.5, 0.3}, {1, 0}, {1, 0.5}}},    // overlapping face on
      {unit, {{0, 2.0000001}, {0, 1}, {1, 1}}},  // just apart along y, turned a quarter
      {unit, {{1.9, 0}, diagonal, {0.5, 0.5}}},  // a diamond's corner in A's face
      // A diamond's corner 0.1 m into A's face: its two incident faces tie exactly (du = -dv),
      // and the first must win; with a large max_separation the neighbouring corners show which.
      {unit, {{1.0 + std::sqrt(0.5) - 0.1, 0}, diagonal, {0.5, 0.5}}},
      {{{0, 0}, {1, 0}, {10, 0.1}}, {{0, 0}, {0, 1}, {10, 0.1}}},  // a cross: the centres meet
      {unit, {{0.2, -0.1}, {1, 0}, {0.1, 0.1}}},                   // B inside A
      {{{1e7, -1e7}, {1, 0}, {2.4, 1}}, {{1e7 + 4.8, -1e7 + 0.5}, {-1, 0}, {2.4, 1}}},
      {unit, {{5, 5}, {1, 0}, {1, 1}}},  // far apart
  };
  // Two points dropped by a zero max_separation keep the normal and face (count 0), and a
  // positive one takes points of pairs apart (1 m: both ends of a diamond's incident face).
  const ManifoldSettings settings[4] = {
      {}, {0.5, 0.98, 0.001}, {0.0, 1.0, 0.0}, {1.0, 0.98, 0.001}};
  Failures f;
  int index = 0;
  for (const ManifoldSettings& s : settings) {
    // Eight copies of the list (two lane groups and a tail of the next length each time).
    for (std::size_t repeat = 0; repeat < 3; ++repeat) {
      std::vector<Obb2> a, b;
      for (std::size_t k = 0; k < cases.size() + repeat; ++k) {
        const auto& [first, second] = cases[k % cases.size()];
        // Both orders, so that B's faces are reference faces as often as A's.
        a.push_back(k % 2 == 0 ? first : second);
        b.push_back(k % 2 == 0 ? second : first);
      }
      checkPairs(a, b, s, f, index);
    }
  }
  EXPECT_EQ(f.count(), 0) << f.report();
}

}  // namespace
}  // namespace cardemo
