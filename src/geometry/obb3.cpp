#include "geometry/obb3.hpp"

#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/finite.hpp"

namespace cardemo {

Obb3 Obb3::fromQuaternion(const Eigen::Vector3d& center, const Eigen::Quaterniond& q,
                          const Eigen::Vector3d& size) {
  const Eigen::Vector4d& raw = q.coeffs();  // (x, y, z, w)
  assert(raw.allFinite());
  const double scale = raw.cwiseAbs().maxCoeff();
  assert(scale > 0.0);
  // Divide by the largest component first so that squaring cannot overflow or underflow; scaling q
  // by a power of two then leaves every rounding, and hence the box, unchanged.
  const Eigen::Vector4d s = raw / scale;
  const Eigen::Vector4d u = s / s.norm();
  const double x = u[0], y = u[1], z = u[2], w = u[3];
  Obb3 box;
  box.center = center;
  box.rotation << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
      2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
      2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y);
  box.half = 0.5 * size;
  return box;
}

Aabb3 Obb3::aabb() const {
  const Eigen::Vector3d r = rotation.cwiseAbs() * half;
  Aabb3 box{center - r, center + r};
  // One ulp outwards so that rounding can never cut off a corner of the box.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    box.min[k] = std::nextafter(box.min[k], -kInf);
    box.max[k] = std::nextafter(box.max[k], kInf);
  }
  return box;
}

namespace {

// a*b - c*d to within 2 ulps of the exact value however much the two products cancel, and exactly
// zero iff a*b == c*d: Kahan's algorithm with an error-free product via fma (Jeannerod, Louvet and
// Muller, "Further analysis of Kahan's algorithm...", Math. Comp. 2013; the TwoProduct of Ogita,
// Rump and Oishi 2005). Explicit std::fma is deterministic under -ffp-contract=off.
double diffOfProducts(double a, double b, double c, double d) {
  const double w = c * d;
  const double err = std::fma(-c, d, w);  // w - c*d, exactly
  const double f = std::fma(a, b, -w);
  return f + err;
}

// u x v with every component correctly signed and accurate to 2 ulps, even for near-parallel u, v.
Eigen::Vector3d accurateCross(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return {diffOfProducts(u.y(), v.z(), u.z(), v.y()), diffOfProducts(u.z(), v.x(), u.x(), v.z()),
          diffOfProducts(u.x(), v.y(), u.y(), v.x())};
}

// The pair seen from A (Gottschalk et al., OBBTree, 1996; Ericson, RTCD 4.4.1).
struct Pose3 {
  Eigen::Vector3d d;     // cB - cA, world frame, subtracted in double first (STYLE 8)
  Eigen::Vector3d ta;    // d in A's frame
  Eigen::Vector3d tb;    // d in B's frame
  Eigen::Matrix3d absR;  // |A^T B|: B's axes in A's frame, absolute values
};

Pose3 relativePose(const Obb3& a, const Obb3& b) {
  const Eigen::Vector3d d = b.center - a.center;
  return {d, a.rotation.transpose() * d, b.rotation.transpose() * d,
          (a.rotation.transpose() * b.rotation).cwiseAbs()};
}

// Gap on face axis k: 0-2 faces of A, 3-5 faces of B. The oracle's face normal is the cross product
// of the other two stored columns, which differs from column k by ~1e-16 in direction: ~1e-14 m.
double faceGap(const Obb3& a, const Obb3& b, const Pose3& p, int k) {
  if (k < 3) return std::abs(p.ta[k]) - a.half[k] - p.absR.row(k).dot(b.half);
  return std::abs(p.tb[k - 3]) - b.half[k - 3] - p.absR.col(k - 3).dot(a.half);
}

// Edge-edge axis a_i x b_j.
//
// Why the world frame and not the usual A-frame entries of R = A^T B: the stored matrices are
// orthonormal only to ~1e-16, so e_i x (A^T b_j) differs from the true a_i x b_j by ~1e-16
// absolute. For edges at angle theta that is a relative error of 1e-16 / theta in the axis
// direction (10% at 1e-15 rad, 1e-7 at 1e-9 rad: 1e-5 m on a 100 m box), whatever precision R has.
// Forming the cross product of the stored columns themselves with an error-free 2x2 determinant
// keeps every component to 2 ulps, so the direction is right to ~1e-16 at any angle; the
// projections are then ordinary O(1) dot products of a well-scaled axis.
//
// Returns false only for an exactly zero cross product: exactly parallel edges add no face to the
// Minkowski difference that the face axes do not already cover, so skipping is exact. No epsilon.
bool edgeGap(const Obb3& a, const Obb3& b, const Eigen::Vector3d& d, int i, int j, double& gap,
             Eigen::Vector3d& axis) {
  const Eigen::Vector3d n = accurateCross(a.rotation.col(i), b.rotation.col(j));
  const double m = n.cwiseAbs().maxCoeff();
  if (m == 0.0) return false;
  // Rescale so the largest component is 1: no underflow in the norm even at tiny angles.
  axis = n / m;
  const double len = axis.norm();
  // a_i . axis and b_j . axis are exactly zero for the exact cross product; dropping them is exact.
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const double ra = a.half[i1] * std::abs(axis.dot(a.rotation.col(i1))) +
                    a.half[i2] * std::abs(axis.dot(a.rotation.col(i2)));
  const double rb = b.half[j1] * std::abs(axis.dot(b.rotation.col(j1))) +
                    b.half[j2] * std::abs(axis.dot(b.rotation.col(j2)));
  gap = (std::abs(axis.dot(d)) - ra - rb) / len;
  axis /= len;
  return true;
}

}  // namespace

SatResult3 collideObb3(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
  const Pose3 p = relativePose(a, b);
  SatResult3 r;
  r.separation = faceGap(a, b, p, 0);
  for (int k = 1; k < 6; ++k) {
    const double g = faceGap(a, b, p, k);
    if (g > r.separation) {
      r.separation = g;
      r.axis_index = k;
    }
  }
  if (r.axis_index < 3) {
    r.normal = a.rotation.col(r.axis_index);
    if (p.ta[r.axis_index] < 0.0) r.normal = -r.normal;
  } else {
    r.normal = b.rotation.col(r.axis_index - 3);
    if (p.tb[r.axis_index - 3] < 0.0) r.normal = -r.normal;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double g = 0.0;
      Eigen::Vector3d axis;
      if (!edgeGap(a, b, p.d, i, j, g, axis) || !(g > r.separation)) continue;
      r.separation = g;
      r.axis_index = 6 + 3 * i + j;
      r.normal = axis.dot(p.d) < 0.0 ? Eigen::Vector3d(-axis) : axis;
    }
  }
  r.hit = r.separation <= 0.0;
  assert(isFinite(r));
  return r;
}

bool overlapObb3(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
  const Pose3 p = relativePose(a, b);
  for (int k = 0; k < 6; ++k) {
    if (faceGap(a, b, p, k) > 0.0) return false;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double g = 0.0;
      Eigen::Vector3d axis;
      if (edgeGap(a, b, p.d, i, j, g, axis) && g > 0.0) return false;
    }
  }
  return true;
}

}  // namespace cardemo
