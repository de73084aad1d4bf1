// manifoldObb2 against its generic twin: the former implementation, with loops over the eight
// faces, dot products with the face normals and generic clipping, kept here as the reference. The
// box-specialised code must give the same manifold (count, face, normal, points, separations,
// features), value for value, over seeded random pairs, hysteresis included.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lab/kernels/manifold2.hpp"
#include "manifold_margin.hpp"
#include "manifold_pairs.hpp"
#include "tests/geometry/random_cases2.hpp"

namespace cardemo {
namespace {

// --- The generic twin (reference face by SAT over face normals, Sutherland-Hodgman clipping) ---

// Outward normal of face k of a box in its own frame: k*90 degrees from local +x.
constexpr double kFaceX[4] = {1.0, 0.0, -1.0, 0.0};
constexpr double kFaceY[4] = {0.0, 1.0, 0.0, -1.0};

// `other` seen from `self`'s frame: centre offset and the other's axes, all in self's local axes.
struct LocalPair {
  Eigen::Vector2d t;  // other's centre minus self's centre, in self's frame
  Eigen::Vector2d u;  // other's local +x in self's frame
  Eigen::Vector2d v;  // other's local +y in self's frame
};

LocalPair localPair(const Obb2& self, const Obb2& other) {
  // Subtract in double first so that the pair is accurate far from the origin (STYLE 8).
  const Eigen::Vector2d d = other.center - self.center;
  const Eigen::Vector2d& a = self.axis;
  const auto toLocal = [&](const Eigen::Vector2d& w) -> Eigen::Vector2d {
    return {a.x() * w.x() + a.y() * w.y(), a.x() * w.y() - a.y() * w.x()};
  };
  return {toLocal(d), toLocal(other.axis), toLocal(other.perp())};
}

Eigen::Vector2d faceNormal(int k) {
  return {kFaceX[k], kFaceY[k]};
}

double faceOffset(const Obb2& box, int k) {
  return k % 2 == 0 ? box.half.x() : box.half.y();
}

// Separation of `other` from face k of `self`: the least signed distance of other's points to the
// face's plane (Box2D b2FindMaxSeparation, specialised to boxes).
double faceSeparation(const Obb2& self, const Obb2& other, const LocalPair& p, int k) {
  const Eigen::Vector2d n = faceNormal(k);
  const double radius =
      other.half.x() * std::abs(n.dot(p.u)) + other.half.y() * std::abs(n.dot(p.v));
  return n.dot(p.t) - faceOffset(self, k) - radius;
}

struct Candidate {
  int face = -1;  // 0-3 of A, 4-7 of B
  double separation = 0.0;
};

Candidate chooseReference(const std::array<double, 8>& seps, const ManifoldSettings& settings,
                          int previous) {
  Candidate best_a{0, seps[0]}, best_b{4, seps[4]};
  for (int k = 1; k < 4; ++k) {
    if (seps[static_cast<std::size_t>(k)] > best_a.separation)
      best_a = {k, seps[static_cast<std::size_t>(k)]};
    if (seps[static_cast<std::size_t>(k + 4)] > best_b.separation) {
      best_b = {k + 4, seps[static_cast<std::size_t>(k + 4)]};
    }
  }
  const Candidate& best = best_b.separation > best_a.separation ? best_b : best_a;
  if (previous >= 0 && previous < 8) {
    const double s = seps[static_cast<std::size_t>(previous)];
    if (s >= best.separation - testing::manifoldMargin(settings, best.separation))
      return {previous, s};
  }
  // A's face is the default; B's must win clearly, so that nearly equal faces do not flip-flop.
  if (best_b.separation > best_a.separation + testing::manifoldMargin(settings, best_a.separation))
    return best_b;
  return best_a;
}

struct ClipVertex {
  Eigen::Vector2d p;
  int id = 0;
};

// Sutherland-Hodgman for a segment against the half-plane n.x <= offset; false when nothing is
// left.
bool clipSegment(std::array<ClipVertex, 2>& seg, const Eigen::Vector2d& n, double offset,
                 int clip_id) {
  const double d0 = n.dot(seg[0].p) - offset;
  const double d1 = n.dot(seg[1].p) - offset;
  if (d0 > 0.0 && d1 > 0.0) return false;
  if (d0 <= 0.0 && d1 <= 0.0) return true;
  const Eigen::Vector2d x = seg[0].p + (d0 / (d0 - d1)) * (seg[1].p - seg[0].p);
  seg[d0 > 0.0 ? 0 : 1] = {x, clip_id};
  return true;
}

Manifold2 genericManifold(const Obb2& a, const Obb2& b, const ManifoldSettings& settings,
                          int previous_reference_face) {
  const LocalPair ab = localPair(a, b);
  const LocalPair ba = localPair(b, a);
  std::array<double, 8> seps{};
  for (int k = 0; k < 4; ++k) {
    seps[static_cast<std::size_t>(k)] = faceSeparation(a, b, ab, k);
    seps[static_cast<std::size_t>(k + 4)] = faceSeparation(b, a, ba, k);
  }
  Manifold2 m;
  const double sat = *std::max_element(seps.begin(), seps.end());
  if (sat > settings.max_separation) return m;

  const Candidate ref = chooseReference(seps, settings, previous_reference_face);
  const bool flip = ref.face >= 4;
  const Obb2& rbox = flip ? b : a;
  const Obb2& ibox = flip ? a : b;
  const LocalPair& p = flip ? ba : ab;
  const int k = ref.face % 4;
  const Eigen::Vector2d n = faceNormal(k);

  // Incident face: the incident box's face whose normal is most anti-parallel to n.
  const Eigen::Vector2d inc_normals[4] = {p.u, p.v, -p.u, -p.v};
  int j = 0;
  for (int i = 1; i < 4; ++i) {
    if (inc_normals[i].dot(n) < inc_normals[j].dot(n)) j = i;
  }
  // Incident corners in the reference frame, in Obb2::corners() order (face j joins j and j+1).
  const Eigen::Vector2d ex = p.u * ibox.half.x(), ey = p.v * ibox.half.y();
  const Eigen::Vector2d corners[4] = {p.t + ex - ey, p.t + ex + ey, p.t - ex + ey, p.t - ex - ey};
  std::array<ClipVertex, 2> seg{{{corners[j], j}, {corners[(j + 1) % 4], (j + 1) % 4}}};

  // Side planes: the reference face runs along the tangent between the box's extents.
  const Eigen::Vector2d tangent{-n.y(), n.x()};
  const double side = faceOffset(rbox, (k + 1) % 4);
  if (!clipSegment(seg, -tangent, side, 4) || !clipSegment(seg, tangent, side, 5)) return m;

  const double offset = faceOffset(rbox, k);
  const Eigen::Vector2d& ru = rbox.axis;
  const Eigen::Vector2d rv = rbox.perp();
  const auto toWorld = [&](const Eigen::Vector2d& q) -> Eigen::Vector2d {
    return rbox.center + ru * q.x() + rv * q.y();
  };
  const Eigen::Vector2d n_world = ru * n.x() + rv * n.y();
  m.normal = flip ? Eigen::Vector2d(-n_world) : n_world;
  m.reference_face = ref.face;
  for (const ClipVertex& cv : seg) {
    const double s = n.dot(cv.p) - offset;
    if (s > settings.max_separation) continue;
    // Points lie on B's surface: on the incident edge when B is incident, else projected onto B's
    // reference face.
    const Eigen::Vector2d on_b = flip ? Eigen::Vector2d(cv.p - s * n) : cv.p;
    m.points[static_cast<std::size_t>(m.count)] = {toWorld(on_b), s, 8 * ref.face + cv.id};
    ++m.count;
  }
  return m;
}

// --- Comparison ---------------------------------------------------------------------------------

using testing::Failures;
using testing::Random;

void expectSame(const Manifold2& fast, const Manifold2& twin, int index, Failures& f) {
  f.check(fast.count == twin.count, index, "count differs");
  f.check(fast.reference_face == twin.reference_face, index, "reference face differs");
  f.check(fast.normal == twin.normal, index, "normal differs");
  for (int i = 0; i < std::min(fast.count, twin.count); ++i) {
    const ContactPoint2& p = fast.points[static_cast<std::size_t>(i)];
    const ContactPoint2& q = twin.points[static_cast<std::size_t>(i)];
    f.check(p.point == q.point, index, "point differs");
    f.check(p.separation == q.separation, index, "separation differs");
    f.check(p.feature == q.feature, index, "feature differs");
  }
}

void runPairs(std::uint64_t seed, double offset, Failures& f, int& with_points) {
  Random rng(seed);
  const int n = testing::scaledCount(100000);
  const ManifoldSettings settings[3] = {{}, {0.0, 1.0, 0.0}, {0.05, 0.95, 0.002}};
  for (int i = 0; i < n; ++i) {
    const auto [a, b] = testing::manifoldPair(rng, offset, i);
    const ManifoldSettings& s = settings[i % 3];
    const int previous = rng.integer(-1, 7);
    const Manifold2 fast = manifoldObb2(a, b, s, previous);
    expectSame(fast, genericManifold(a, b, s, previous), i, f);
    with_points += fast.count > 0 ? 1 : 0;
  }
}

TEST(Manifold2Twin, SameManifoldAsTheGenericTwin) {
  Failures f;
  int with_points = 0;
  runPairs(3101, 100.0, f, with_points);
  EXPECT_EQ(f.count(), 0) << f.report();
  EXPECT_GT(with_points, testing::scaledCount(100000) / 4);
}

TEST(Manifold2Twin, SameManifoldFarFromTheOrigin) {
  Failures f;
  int with_points = 0;
  runPairs(3102, 1e7, f, with_points);
  EXPECT_EQ(f.count(), 0) << f.report();
  EXPECT_GT(with_points, testing::scaledCount(100000) / 4);
}

}  // namespace
}  // namespace cardemo
