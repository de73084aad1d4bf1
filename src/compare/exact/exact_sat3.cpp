/// Exact SAT oracle for two 3D boxes (parallelepipeds over the stored double matrices), GMP.

#include <gmpxx.h>

#include <array>

#include "compare/exact/dyadic.hpp"
#include "compare/exact/exact_numbers.hpp"
#include "compare/exact/exact_sat.hpp"

namespace cardemo::exact {
namespace {

using QVec = std::array<Dyadic, 3>;

// Exact dyadic arithmetic; the only inexact steps are the square root and division by the axis
// length.
QVec toQ(const Eigen::Vector3d& v) {
  return {Dyadic(v.x()), Dyadic(v.y()), Dyadic(v.z())};
}

QVec cross(const QVec& u, const QVec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Dyadic dot(const QVec& u, const QVec& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

bool isZero(const QVec& v) {
  return v[0].sign() == 0 && v[1].sign() == 0 && v[2].sign() == 0;
}

// One box taken exactly: { center + M p : |p_i| <= half_i }, M's columns as stored (not assumed
// orthonormal), so it is a parallelepiped with edge vectors = columns.
struct QBox {
  QVec center;
  std::array<QVec, 3> edge;
  std::array<Dyadic, 3> half;
};

QBox toQ(const Obb3& box) {
  QBox q{toQ(box.center), {}, {}};
  for (int k = 0; k < 3; ++k) {
    q.edge[k] = toQ(box.rotation().col(k));
    q.half[k] = Dyadic(box.half[k]);
  }
  return q;
}

// Support radius of a parallelepiped along n: sum_i half_i |n . edge_i|.
Dyadic radius(const QBox& box, const QVec& n) {
  Dyadic r;
  for (int k = 0; k < 3; ++k) r += box.half[k] * abs(dot(n, box.edge[k]));
  return r;
}

}  // namespace

ExactResult collideObb3(const Obb3& a, const Obb3& b) {
  const QBox qa = toQ(a);
  const QBox qb = toQ(b);
  const QVec d{qb.center[0] - qa.center[0], qb.center[1] - qa.center[1],
               qb.center[2] - qa.center[2]};

  // Candidate axes: the face normals of both parallelepipeds (cross products of edge pairs) and
  // the 9 edge-edge cross products; this set is complete for two convex polyhedra (Gottschalk
  // 1996).
  std::array<QVec, 15> axes;
  for (int k = 0; k < 3; ++k) {
    axes[k] = cross(qa.edge[(k + 1) % 3], qa.edge[(k + 2) % 3]);
    axes[3 + k] = cross(qb.edge[(k + 1) % 3], qb.edge[(k + 2) % 3]);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) axes[6 + 3 * i + j] = cross(qa.edge[i], qb.edge[j]);
  }

  bool hit = true;
  bool any = false;
  mpf_class best(0, kFloatBits);
  for (const QVec& n : axes) {
    // A zero cross product comes from exactly parallel edges, which add no face to the Minkowski
    // difference that the face normals do not already cover.
    if (isZero(n)) continue;
    const Dyadic gap = abs(dot(n, d)) - radius(qa, n) - radius(qb, n);
    if (gap.sign() > 0) hit = false;
    const mpf_class len = sqrt(dot(n, n).toFloat(kFloatBits));
    const mpf_class sep = gap.toFloat(kFloatBits) / len;
    if (!any || sep > best) best = sep;
    any = true;
  }
  return {hit, best.get_d()};
}

}  // namespace cardemo::exact
