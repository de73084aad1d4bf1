#include "geometry/obb3.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/finite.hpp"
#include "geometry/obb3_edge_bound.hpp"
#include "geometry/obb3_normal.hpp"

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
  // The sum written out, not Eigen's norm(): Eigen sums in the order of its vector packets, here
  // (x^2 + z^2) + (y^2 + w^2) with SSE2 and another order without SIMD (the WebAssembly build),
  // which rounds differently. This is the SSE2 order, so the native boxes keep their bits.
  const double length = std::sqrt((s[0] * s[0] + s[2] * s[2]) + (s[1] * s[1] + s[3] * s[3]));
  const Eigen::Vector4d u = s / length;
  const double x = u[0], y = u[1], z = u[2], w = u[3];
  Eigen::Matrix3d m;
  m << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
      2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
      2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y);
  Obb3 box;
  box.center = center;
  box.setRotation(m);
  box.half = 0.5 * size;
  return box;
}

void Obb3::setRotation(const Eigen::Matrix3d& m) {
  rotation_ = m;
  frame_defect_ = cardemo::frameDefect(m);
}

Aabb3 Obb3::aabb() const {
  // Each row's sum written out, left to right (see dot3 below for why not Eigen's product).
  const Eigen::Matrix3d& m = rotation_;
  Eigen::Vector3d r;
  for (int k = 0; k < 3; ++k) {
    r[k] = std::abs(m(k, 0)) * half[0] + std::abs(m(k, 1)) * half[1] + std::abs(m(k, 2)) * half[2];
  }
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

// Three doubles as two pairs, the fourth lane padding: the x86-64 baseline (SSE2) works on two
// doubles per instruction, and GCC and Clang lower these vector types to it (to scalars on targets
// without). Each lane does the IEEE operations of the scalar formula it stands for, in its order.
using V2 = double __attribute__((vector_size(16)));
using M2 = long long __attribute__((vector_size(16)));

struct V3 {
  V2 lo;  // lanes 0, 1
  V2 hi;  // lane 2, padding
};

[[gnu::always_inline]] inline V3 operator+(const V3& u, const V3& v) {
  return {u.lo + v.lo, u.hi + v.hi};
}
[[gnu::always_inline]] inline V3 operator-(const V3& u, const V3& v) {
  return {u.lo - v.lo, u.hi - v.hi};
}
[[gnu::always_inline]] inline V3 operator*(const V3& u, const V3& v) {
  return {u.lo * v.lo, u.hi * v.hi};
}
[[gnu::always_inline]] inline V3 operator*(const V3& u, double s) {
  return {u.lo * V2{s, s}, u.hi * V2{s, s}};
}
[[gnu::always_inline]] inline V2 abs2(V2 x) {
  constexpr long long kNoSign = 0x7fffffffffffffffLL;
  return reinterpret_cast<V2>(reinterpret_cast<M2>(x) & M2{kNoSign, kNoSign});
}
[[gnu::always_inline]] inline V3 abs3(const V3& u) {
  return {abs2(u.lo), abs2(u.hi)};
}
// Lane k of next1(u) is lane k + 1 (mod 3) of u, of next2(u) lane k + 2.
[[gnu::always_inline]] inline V3 next1(const V3& u) {
  return {__builtin_shufflevector(u.lo, u.hi, 1, 2), __builtin_shufflevector(u.lo, u.lo, 0, 0)};
}
[[gnu::always_inline]] inline V3 next2(const V3& u) {
  return {__builtin_shufflevector(u.hi, u.lo, 0, 2), __builtin_shufflevector(u.lo, u.lo, 1, 1)};
}
[[gnu::always_inline]] inline V3 gather3(double x, double y, double z) {
  return {V2{x, y}, V2{z, z}};
}
[[gnu::always_inline]] inline double lane(const V3& u, int k) {
  return k == 0 ? u.lo[0] : k == 1 ? u.lo[1] : u.hi[0];
}
template <int K>
[[gnu::always_inline]] inline double lane(const V3& u) {
  if constexpr (K < 2) return u.lo[K];
  return u.hi[0];
}
// Lanes 0-2 of a comparison's result all true.
[[gnu::always_inline]] inline bool all3(M2 lo, M2 hi) {
  return (lo[0] & lo[1] & hi[0]) != 0;
}

// The pair seen from A (Gottschalk et al., OBBTree, 1996; Ericson, RTCD 4.4.1). The vectors run
// over A's axes k; col[j] is column j of R = A^T B.
struct Pose3 {
  Eigen::Vector3d d;  // cB - cA, world frame, subtracted in double first (STYLE 8)
  V3 t;               // d in A's frame: a_k . d
  double tb[3];       // d in B's frame: b_k . d
  V3 col[3];          // a_k . b_j
  V3 abscol[3];       // |a_k . b_j|
  V3 face_a;          // gaps on A's faces
  double face_b[3];   // gaps on B's faces
  [[nodiscard]] double r(int k, int j) const { return lane(col[j], k); }
  [[nodiscard]] double tk(int k) const { return lane(t, k); }
  [[nodiscard]] double tbk(int j) const { return tb[j]; }
  [[nodiscard]] double face(int k) const { return k < 3 ? lane(face_a, k) : face_b[k - 3]; }
};

// u . v left to right. Eigen's dot(), norm() and products of 3-vectors sum in the order of its
// vector packets, left to right with SSE2 but x + (y + z) without SIMD (the WebAssembly build):
// the 3D results are the same bits on every platform only with the sums written out.
[[gnu::always_inline]] inline double dot3(const double* u, const double* v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// Column k of the box's rotation, for dot3.
const double* columnOf(const Obb3& box, int k) {
  return box.rotation().data() + 3 * k;  // column-major
}

// Calls f(std::integral_constant<int, K>{}) for K = 0, ..., N - 1: compile-time indices, so every
// entry below is a named value the compiler keeps in a register (runtime loops over the 3x3 arrays
// stay loops at -O2).
template <class F, int... K>
[[gnu::always_inline]] inline void forEach(const F& f, std::integer_sequence<int, K...>) {
  (f(std::integral_constant<int, K>{}), ...);
}

template <int N, class F>
[[gnu::always_inline]] inline void staticFor(const F& f) {
  forEach(f, std::make_integer_sequence<int, N>{});
}

// Face gaps, 0-2 faces of A, 3-5 of B. The oracle's face normal is the cross product of the other
// two stored columns, which differs from column k by ~1e-16 in direction: ~1e-14 m. Lane k of t and
// of col[j] is dot3 of A's column k with d and b_j, term by term in dot3's order.
[[gnu::always_inline]] inline Pose3 relativePose(const Obb3& a, const Obb3& b) {
  Pose3 p;
  p.d = b.center - a.center;
  const double* ra = a.rotation().data();  // column-major: column k at 3k
  const double* rb = b.rotation().data();
  const double* hb = b.half.data();
  const V3 ax = gather3(ra[0], ra[3], ra[6]);  // component x of A's three columns
  const V3 ay = gather3(ra[1], ra[4], ra[7]);
  const V3 az = gather3(ra[2], ra[5], ra[8]);
  const V3 ha = gather3(a.half.x(), a.half.y(), a.half.z());
  p.t = ax * p.d.x() + ay * p.d.y() + az * p.d.z();
  staticFor<3>([&](auto jc) {
    constexpr std::size_t j = decltype(jc)::value;
    p.col[j] = ax * rb[3 * j] + ay * rb[3 * j + 1] + az * rb[3 * j + 2];
    p.abscol[j] = abs3(p.col[j]);
    p.tb[j] = dot3(rb + 3 * j, p.d.data());
  });
  p.face_a = abs3(p.t) - ha - (p.abscol[0] * hb[0] + p.abscol[1] * hb[1] + p.abscol[2] * hb[2]);
  staticFor<3>([&](auto jc) {
    constexpr int j = decltype(jc)::value;
    const V3 radius = p.abscol[j] * ha;
    p.face_b[j] = std::abs(p.tb[j]) - hb[j] - (radius.lo[0] + radius.lo[1] + radius.hi[0]);
  });
  return p;
}

// The box's obb3_detail::BoxNumbers: its members are three runs of doubles, in that order, with no
// padding between them.
const double* numbersOf(const Obb3& box) {
  const double* numbers = box.center.data();
  assert(box.half.data() == numbers + obb3_detail::BoxNumbers::kHalf &&
         box.rotation().data() == numbers + obb3_detail::BoxNumbers::kRotation);
  return numbers;
}

// The A-frame filter (the batch kernels' one, batch_kernels.hpp; docs/architecture.md, "The 3D
// filter"; obb3_detail::edgeBound computes it, for this file and the AVX2 kernel alike). The edge
// axis a_i x b_j in A's frame is e_i x (A^T b_j): its gap needs only entries of R = A^T B and t, a
// dozen operations instead of the accurate form's fifty (with six fma calls, library calls on a
// build without -mfma). Against the gap on the stored columns' exact cross product, which edgeGap
// below computes to a few ulps, its error is within `bound` (frameDefect widens it); a gap beyond
// the bound has the accurate gap's sign, the others are recomputed accurately, so every verdict is
// the accurate one. A normalised gap is within 2^-40 of the pair's scale of the accurate one when
// the squared axis length clears `min_length2`.
[[gnu::always_inline]] inline obb3_detail::EdgeBound edgeFilter(const Obb3& a, const Obb3& b) {
  return obb3_detail::edgeBound(numbersOf(a), numbersOf(b),
                                std::max(a.frameDefect(), b.frameDefect()));
}

// Edge axes a_i x b_j in A's frame, gap times axis length and squared length: lane i of gap[j] and
// of length2[j] is edge axis (i, j), e = 3i + j.
struct FastEdges {
  V3 gap[3];
  V3 length2[3];
  [[nodiscard]] double gapOf(int e) const { return lane(gap[e % 3], e / 3); }
  [[nodiscard]] double length2Of(int e) const { return lane(length2[e % 3], e / 3); }
};

// All nine, three per column j of R. Lane i is the scalar formula, with i1, i2 = i + 1, i + 2 and
// j1, j2 = j + 1, j + 2 (mod 3): e_i x r_j = r_i1j e_i2 - r_i2j e_i1; its dot products with A's
// other axes are R entries of rows i2 and i1, with B's other axes entries of row i (B's columns
// j x j1 = j2):
//   along = t_i2 r_i1j - t_i1 r_i2j,  ra = ha_i1 |r_i2j| + ha_i2 |r_i1j|,
//   rb = |r_ij2| hb_j1 + |r_ij1| hb_j2,  gap = |along| - ra - rb,  length2 = r_i1j^2 + r_i2j^2.
[[gnu::always_inline]] inline FastEdges fastEdges(const Obb3& a, const Obb3& b, const Pose3& p) {
  FastEdges out;
  const V3 ha = gather3(a.half.x(), a.half.y(), a.half.z());
  const V3 t1 = next1(p.t), t2 = next2(p.t);
  const V3 ha1 = next1(ha), ha2 = next2(ha);
  const double* hb = b.half.data();
  staticFor<3>([&](auto jc) {
    constexpr int j = decltype(jc)::value, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const V3 r1 = next1(p.col[j]), r2 = next2(p.col[j]);
    const V3 along = t2 * r1 - t1 * r2;
    const V3 ra = ha1 * abs3(r2) + ha2 * abs3(r1);
    const V3 rb = p.abscol[j2] * hb[j1] + p.abscol[j1] * hb[j2];
    out.gap[j] = abs3(along) - ra - rb;
    out.length2[j] = r1 * r1 + r2 * r2;
  });
  return out;
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
  const Eigen::Vector3d n = accurateCross(a.rotation().col(i), b.rotation().col(j));
  const double m = n.cwiseAbs().maxCoeff();
  if (m == 0.0) return false;
  // Rescale so the largest component is 1: no underflow in the norm even at tiny angles.
  axis = n / m;
  const double* u = axis.data();
  const double len = std::sqrt(dot3(u, u));
  // a_i . axis and b_j . axis are exactly zero for the exact cross product; dropping them is exact.
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const double ra = a.half[i1] * std::abs(dot3(u, columnOf(a, i1))) +
                    a.half[i2] * std::abs(dot3(u, columnOf(a, i2)));
  const double rb = b.half[j1] * std::abs(dot3(u, columnOf(b, j1))) +
                    b.half[j2] * std::abs(dot3(u, columnOf(b, j2)));
  gap = (std::abs(dot3(u, d.data())) - ra - rb) / len;
  axis /= len;
  return true;
}

// Lane by lane x where `take_x`, else y.
[[gnu::always_inline]] inline V2 select2(M2 take_x, V2 x, V2 y) {
  return reinterpret_cast<V2>((take_x & reinterpret_cast<M2>(x)) |
                              (~take_x & reinterpret_cast<M2>(y)));
}

// Lane by lane max(u, v) (u where u > v).
[[gnu::always_inline]] inline V2 max2(V2 u, V2 v) {
  return select2(u > v, u, v);
}

// The first largest of the fifteen candidate gaps (faces, then edges 3i + j): `!(g > best)` keeps
// the earlier axis on a tie, as the accurate loop does.
[[gnu::always_inline]] inline void pickLargest(double g, int index, double& best, int& best_index) {
  const bool larger = g > best;
  best = larger ? g : best;
  best_index = larger ? index : best_index;
}

// gap / sqrt(length2) lane by lane; on SSE2 one sqrtpd and one divpd, the same correctly rounded
// operations as the scalar form, so the same bits either way.
[[gnu::always_inline]] inline V2 normalised2(V2 gap, V2 length2) {
#if defined(__SSE2__)
  return gap / static_cast<V2>(_mm_sqrt_pd(length2));
#else
  return V2{gap[0] / std::sqrt(length2[0]), gap[1] / std::sqrt(length2[1])};
#endif
}

// The largest of the faces' winner (best, best_index) and the nine fast edge gaps: the gaps
// normalised together, then picked in axis order.
[[gnu::always_inline]] inline void largestNormalised(const FastEdges& fast, double& best,
                                                     int& best_index) {
  V3 g[3];
  staticFor<3>([&](auto jc) {
    constexpr int j = decltype(jc)::value;
    g[j] = {normalised2(fast.gap[j].lo, fast.length2[j].lo),
            normalised2(fast.gap[j].hi, fast.length2[j].hi)};
  });
  staticFor<9>([&](auto ec) {
    constexpr int e = decltype(ec)::value, i = e / 3, j = e % 3;
    pickLargest(lane<i>(g[j]), 6 + e, best, best_index);
  });
}

}  // namespace

namespace {

// collideObb3 with two SSE2 registers per 3-vector. lab/geometry/obb3_paths.cpp calls collideObb3
// where its AVX2 kernel leaves a pair undecided; not inlined, so that its caller keeps a small
// frame.
[[gnu::noinline]] SatResult3 collideSse2(const Obb3& a, const Obb3& b) {
  const Pose3 p = relativePose(a, b);
  SatResult3 r;
  double best = p.face_a.lo[0];
  int best_index = 0;
  pickLargest(p.face_a.lo[1], 1, best, best_index);
  pickLargest(p.face_a.hi[0], 2, best, best_index);
  staticFor<3>([&](auto jc) {
    constexpr int j = decltype(jc)::value;
    pickLargest(p.face_b[j], 3 + j, best, best_index);
  });
  const FastEdges fast = fastEdges(a, b, p);
  const obb3_detail::EdgeBound filter = edgeFilter(a, b);
  // The usual case: every edge gap clears the filter's bound on a long enough axis, so all nine
  // candidates are the fast ones, normalised together and compared without branches.
  const V2 bound{filter.bound, filter.bound};
  const V2 min_length2{filter.min_length2, filter.min_length2};
  M2 sure_lo = abs2(fast.gap[0].lo) > bound, sure_hi = abs2(fast.gap[0].hi) > bound;
  staticFor<3>([&](auto jc) {
    constexpr int j = decltype(jc)::value;
    if constexpr (j > 0) {
      sure_lo &= abs2(fast.gap[j].lo) > bound;
      sure_hi &= abs2(fast.gap[j].hi) > bound;
    }
    sure_lo &= fast.length2[j].lo > min_length2;
    sure_hi &= fast.length2[j].hi > min_length2;
  });
  if (all3(sure_lo, sure_hi)) {
    largestNormalised(fast, best, best_index);
    r.separation = best;
    r.axis_index = best_index;
    if (best_index >= 6) {
      r.normal = obb3_detail::fastEdgeNormal(a, p, best_index);
      r.hit = best <= 0.0;
      assert(isFinite(r));
      return r;
    }
  } else {
    // Some edge gap lies within the bound: edge by edge, the accurate axis where it does.
    r.separation = best;
    r.axis_index = best_index;
    bool fast_winner = false;
    bool accurate_winner = false;
    for (int e = 0; e < 9; ++e) {
      const double gap = fast.gapOf(e), length2 = fast.length2Of(e);
      if (std::abs(gap) > filter.bound && length2 > filter.min_length2) {
        const double ge = gap / std::sqrt(length2);
        if (!(ge > r.separation)) continue;
        r.separation = ge;
        r.axis_index = 6 + e;
        fast_winner = true;
        accurate_winner = false;
        continue;
      }
      double ge = 0.0;
      Eigen::Vector3d axis;
      if (!edgeGap(a, b, p.d, e / 3, e % 3, ge, axis) || !(ge > r.separation)) continue;
      r.separation = ge;
      r.axis_index = 6 + e;
      r.normal = dot3(axis.data(), p.d.data()) < 0.0 ? Eigen::Vector3d(-axis) : axis;
      fast_winner = false;
      accurate_winner = true;
    }
    if (fast_winner || accurate_winner) {
      if (fast_winner) {
        r.normal = obb3_detail::fastEdgeNormal(a, p, r.axis_index);
      }
      r.hit = r.separation <= 0.0;
      assert(isFinite(r));
      return r;
    }
  }
  // A face axis wins.
  r.normal = obb3_detail::winningNormal(a, b, p, r.axis_index);
  r.hit = r.separation <= 0.0;
  assert(isFinite(r));
  return r;
}

// overlapObb3 with two SSE2 registers per 3-vector; not inlined, as collideSse2.
[[gnu::noinline]] bool overlapSse2(const Obb3& a, const Obb3& b) {
  const Pose3 p = relativePose(a, b);
  const double face = std::max(
      {p.face_a.lo[0], p.face_a.lo[1], p.face_a.hi[0], p.face_b[0], p.face_b[1], p.face_b[2]});
  if (face > 0.0) return false;
  const FastEdges fast = fastEdges(a, b, p);
  const V2 lo = max2(max2(fast.gap[0].lo, fast.gap[1].lo), fast.gap[2].lo);
  const V2 hi = max2(max2(fast.gap[0].hi, fast.gap[1].hi), fast.gap[2].hi);
  const double largest = std::max({lo[0], lo[1], hi[0]});
  const obb3_detail::EdgeBound filter = edgeFilter(a, b);
  if (largest > filter.bound) return false;
  if (largest < -filter.bound) return true;
  for (int e = 0; e < 9; ++e) {
    if (fast.gapOf(e) < -filter.bound) continue;
    double g = 0.0;
    Eigen::Vector3d axis;
    if (edgeGap(a, b, p.d, e / 3, e % 3, g, axis) && g > 0.0) return false;
  }
  return true;
}

}  // namespace

SatResult3 collideObb3(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
  return collideSse2(a, b);
}

bool overlapObb3(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
  return overlapSse2(a, b);
}

// Plain scalar code: Eigen's 3-vector expressions cost several times as much here, and this runs
// for every pair that the face axes do not separate.
double frameDefect(const Eigen::Matrix3d& m) {
  const double* c = m.data();  // column k at 3k
  double defect = 0.0;
  double norms = 0.0;  // sum of the squared column norms: NaN or infinite iff some entry is
  staticFor<3>([&](auto kc) {
    constexpr std::size_t k = decltype(kc)::value, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    staticFor<3 - static_cast<int>(k)>([&](auto lc) {
      constexpr std::size_t l = k + decltype(lc)::value;
      const double g = dot3(c + 3 * k, c + 3 * l);
      if constexpr (k == l) norms += g;
      defect = std::max(defect, std::abs(g - (k == l ? 1.0 : 0.0)));
    });
    const double* u = c + 3 * k1;
    const double* v = c + 3 * k2;
    defect = std::max(defect, std::abs(u[1] * v[2] - u[2] * v[1] - c[3 * k]));
    defect = std::max(defect, std::abs(u[2] * v[0] - u[0] * v[2] - c[3 * k + 1]));
    defect = std::max(defect, std::abs(u[0] * v[1] - u[1] * v[0] - c[3 * k + 2]));
  });
  // std::max drops a NaN; the norms keep it (and report overflowing entries as infinite too).
  return norms < std::numeric_limits<double>::infinity() ? defect + 0x1p-51
                                                         : std::numeric_limits<double>::infinity();
}

}  // namespace cardemo
