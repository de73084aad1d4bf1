#pragma once
/// Internal to the batch kernels: each kernel written once over a "lane" type, so the portable
/// build (a lane is one double) and the AVX2 build (a lane is four doubles) run the same IEEE
/// operations in the same order and give bit-identical results.
///
/// A lane type L provides: L::kWidth, L::Mask, L::load(const double*), L::splat(double),
/// + - * / and unary -, abs, sqrt, fma (correctly rounded a*b+c), gt, lt, mask | and &,
/// select(mask, if_true, if_false), store(double*, L) and storeHits(uint8_t*, separated mask).
//
// Included by exactly two translation units, batch_portable.cpp and batch_avx2.cpp (the latter
// compiled with -mavx2 -mfma). Everything here has internal linkage, so the linker can never
// substitute one instantiation for the other. Multiplications and additions are written out
// separately and -ffp-contract=off forbids fusing them; the only fused operations are the
// explicit fma calls of the 3D edge axes, which are correctly rounded on both paths.

#include <cstddef>
#include <cstdint>

#include "geometry/batch_entry.hpp"

// Every kernel is inlined into its driver loop, so the query box's broadcast values are loaded
// once per call rather than once per lane group (GCC and Clang both honour the attribute).
#define CARDEMO_BATCH_INLINE [[gnu::always_inline]] inline

namespace cardemo::batch_detail {
namespace {

// ---------------------------------------------------------------------------------------------
// 2D: the same expressions, in the same order, as overlapObb2 / collideObb2 (sat_obb2.cpp), so a
// batch result equals the scalar one bit for bit.

template <class L>
struct Pose2Lanes {
  L tx, ty;    // B's centre minus A's centre, in A's frame
  L c, s;      // cos and sin of B's heading relative to A
  L ac, as;    // |c|, |s|
  L tbx, tby;  // the centre offset in B's frame
  L bux, buy;  // B's axis, world frame
  L hbx, hby;  // B's half extents
};

template <class L>
CARDEMO_BATCH_INLINE Pose2Lanes<L> pose2(const Box2One& a, const Box2Arrays& b, std::size_t i) {
  // Subtract the centres in double first (STYLE 8): exact enough 1e7 m from the origin.
  const L dx = L::load(b.cx + i) - L::splat(a.cx);
  const L dy = L::load(b.cy + i) - L::splat(a.cy);
  const L ux = L::splat(a.ux), uy = L::splat(a.uy);
  Pose2Lanes<L> p;
  p.bux = L::load(b.ux + i);
  p.buy = L::load(b.uy + i);
  p.hbx = L::load(b.hx + i);
  p.hby = L::load(b.hy + i);
  p.tx = ux * dx + uy * dy;
  p.ty = ux * dy - uy * dx;
  p.c = ux * p.bux + uy * p.buy;
  p.s = ux * p.buy - uy * p.bux;
  p.ac = abs(p.c);
  p.as = abs(p.s);
  p.tbx = p.c * p.tx + p.s * p.ty;
  p.tby = p.c * p.ty - p.s * p.tx;
  return p;
}

// Separated on some axis (Gottschalk et al., OBBTree, 1996): |t| > rA + rB with B's radius
// |R| hB on A's axes and A's radius on B's axes.
template <class L>
CARDEMO_BATCH_INLINE typename L::Mask separated2(const Box2One& a, const Box2Arrays& b,
                                                 std::size_t i) {
  const Pose2Lanes<L> p = pose2<L>(a, b, i);
  const L hax = L::splat(a.hx), hay = L::splat(a.hy);
  typename L::Mask out = gt(abs(p.tx), hax + p.ac * p.hbx + p.as * p.hby);
  out = out | gt(abs(p.ty), hay + p.as * p.hbx + p.ac * p.hby);
  out = out | gt(abs(p.tbx), p.hbx + p.ac * hax + p.as * hay);
  out = out | gt(abs(p.tby), p.hby + p.as * hax + p.ac * hay);
  return out;
}

// -x where the mask is set, else x. A lane type may provide a cheaper overload (a masked sign
// flip); any form is exact, since negation only flips the sign bit.
template <class L, class M>
CARDEMO_BATCH_INLINE L negateWhere(const M& m, const L& x) {
  return select(m, -x, x);
}

template <class L>
CARDEMO_BATCH_INLINE void collide2(const Box2One& a, const Box2Arrays& b, std::size_t i,
                                   const Sat2Out& out, std::size_t o) {
  const Pose2Lanes<L> p = pose2<L>(a, b, i);
  const L hax = L::splat(a.hx), hay = L::splat(a.hy);
  const L ux = L::splat(a.ux), uy = L::splat(a.uy);
  const L g0 = abs(p.tx) - (hax + p.ac * p.hbx + p.as * p.hby);
  const L g1 = abs(p.ty) - (hay + p.as * p.hbx + p.ac * p.hby);
  const L g2 = abs(p.tbx) - (p.hbx + p.ac * hax + p.as * hay);
  const L g3 = abs(p.tby) - (p.hby + p.as * hax + p.ac * hay);
  // The first largest gap wins (A's x, A's y, B's x, B's y), as in collideObb2.
  L best = g0, nx = ux, ny = uy, along = p.tx;
  const typename L::Mask m1 = gt(g1, best);
  best = select(m1, g1, best);
  nx = select(m1, -uy, nx);
  ny = select(m1, ux, ny);
  along = select(m1, p.ty, along);
  const typename L::Mask m2 = gt(g2, best);
  best = select(m2, g2, best);
  nx = select(m2, p.bux, nx);
  ny = select(m2, p.buy, ny);
  along = select(m2, p.tbx, along);
  const typename L::Mask m3 = gt(g3, best);
  best = select(m3, g3, best);
  nx = select(m3, -p.buy, nx);
  ny = select(m3, p.bux, ny);
  along = select(m3, p.tby, along);
  // Point the axis from A towards B.
  const typename L::Mask flip = lt(along, L::splat(0.0));
  store(out.separation + o, best);
  store(out.nx + o, negateWhere(flip, nx));
  store(out.ny + o, negateWhere(flip, ny));
}

// ---------------------------------------------------------------------------------------------
// 3D: the 15 axes of collideObb3 (obb3.cpp) with the same error-free edge axes; the order of
// operations is this file's own, so results agree with the scalar code to rounding, not bits.

template <class L>
struct V3 {
  L x, y, z;
};

template <class L>
CARDEMO_BATCH_INLINE L dot(const V3<L>& u, const V3<L>& v) {
  return u.x * v.x + u.y * v.y + u.z * v.z;
}

// a*b - c*d to 2 ulps, exactly zero iff a*b == c*d (Kahan's algorithm with an fma TwoProduct;
// Jeannerod, Louvet and Muller, Math. Comp. 2013), as diffOfProducts in obb3.cpp.
template <class L>
CARDEMO_BATCH_INLINE L diffOfProducts(const L& a, const L& b, const L& c, const L& d) {
  const L w = c * d;
  const L err = fma(-c, d, w);
  const L f = fma(a, b, -w);
  return f + err;
}

template <class L>
CARDEMO_BATCH_INLINE V3<L> accurateCross(const V3<L>& u, const V3<L>& v) {
  return {diffOfProducts(u.y, v.z, u.z, v.y), diffOfProducts(u.z, v.x, u.x, v.z),
          diffOfProducts(u.x, v.y, u.y, v.x)};
}

// Below this squared length an edge axis is treated as exactly parallel and skipped: its
// components are under 2^-480 (an angle under 1e-144 rad between the edges), where the face axes
// decide the pair to far better than any tolerance, and squaring could underflow.
constexpr double kMinAxisLength2 = 0x1p-960;

// Edge-axis gap: separation along a_i x b_j, times |a_i x b_j| (unnormalised), its squared length,
// and whether the axis is used.
template <class L>
struct EdgeGap {
  L gap;
  L length2;
  typename L::Mask valid;
};

template <class L>
struct Pair3Lanes {
  V3<L> d;     // B's centre minus A's centre, world frame
  V3<L> a[3];  // A's axes (the same in every lane)
  V3<L> b[3];  // B's axes
  L ha[3], hb[3];
  L face[6];  // gaps on A's faces 0-2 and B's faces 0-2
};

template <class L>
CARDEMO_BATCH_INLINE Pair3Lanes<L> pair3(const Box3One& a, const Box3Arrays& b, std::size_t i) {
  Pair3Lanes<L> p;
  p.d = {L::load(b.cx + i) - L::splat(a.cx), L::load(b.cy + i) - L::splat(a.cy),
         L::load(b.cz + i) - L::splat(a.cz)};
  for (int j = 0; j < 3; ++j) {
    p.a[j] = {L::splat(a.r[3 * j]), L::splat(a.r[3 * j + 1]), L::splat(a.r[3 * j + 2])};
    p.b[j] = {L::load(b.r[3 * j] + i), L::load(b.r[3 * j + 1] + i), L::load(b.r[3 * j + 2] + i)};
  }
  p.ha[0] = L::splat(a.hx);
  p.ha[1] = L::splat(a.hy);
  p.ha[2] = L::splat(a.hz);
  p.hb[0] = L::load(b.hx + i);
  p.hb[1] = L::load(b.hy + i);
  p.hb[2] = L::load(b.hz + i);
  // Face axes (Gottschalk et al. 1996; Ericson, RTCD 4.4.1): |A^T B| and the offset in each frame.
  L absR[3][3];
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) absR[k][j] = abs(dot(p.a[k], p.b[j]));
  }
  for (int k = 0; k < 3; ++k) {
    const L rb = absR[k][0] * p.hb[0] + absR[k][1] * p.hb[1] + absR[k][2] * p.hb[2];
    p.face[k] = abs(dot(p.a[k], p.d)) - p.ha[k] - rb;
  }
  for (int j = 0; j < 3; ++j) {
    const L ra = absR[0][j] * p.ha[0] + absR[1][j] * p.ha[1] + absR[2][j] * p.ha[2];
    p.face[3 + j] = abs(dot(p.b[j], p.d)) - p.hb[j] - ra;
  }
  return p;
}

// Why the world frame and the error-free cross product: see edgeGap in obb3.cpp. The radii drop
// a_i . n and b_j . n, which are exactly zero for the exact cross product.
template <class L>
CARDEMO_BATCH_INLINE EdgeGap<L> edgeGap(const Pair3Lanes<L>& p, int i, int j) {
  const V3<L> n = accurateCross(p.a[i], p.b[j]);
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const L ra = p.ha[i1] * abs(dot(n, p.a[i1])) + p.ha[i2] * abs(dot(n, p.a[i2]));
  const L rb = p.hb[j1] * abs(dot(n, p.b[j1])) + p.hb[j2] * abs(dot(n, p.b[j2]));
  const L length2 = dot(n, n);
  return {abs(dot(n, p.d)) - ra - rb, length2, gt(length2, L::splat(kMinAxisLength2))};
}

template <class L>
CARDEMO_BATCH_INLINE typename L::Mask separated3(const Box3One& a, const Box3Arrays& b,
                                                 std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  const L zero = L::splat(0.0);
  typename L::Mask out = gt(p.face[0], zero);
  for (int k = 1; k < 6; ++k) out = out | gt(p.face[k], zero);
  for (int e = 0; e < 9; ++e) {
    const EdgeGap<L> g = edgeGap(p, e / 3, e % 3);
    out = out | (g.valid & gt(g.gap, zero));
  }
  return out;
}

template <class L>
CARDEMO_BATCH_INLINE L separation3(const Box3One& a, const Box3Arrays& b, std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  L best = p.face[0];
  for (int k = 1; k < 6; ++k) best = select(gt(p.face[k], best), p.face[k], best);
  for (int e = 0; e < 9; ++e) {
    const EdgeGap<L> g = edgeGap(p, e / 3, e % 3);
    const L gap = g.gap / sqrt(g.length2);
    best = select(g.valid & gt(gap, best), gap, best);
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Drivers: whole lane groups, then a tail group padded with copies of the last box.

template <class L, class Arrays, std::size_t kFields>
struct PaddedTail {
  double values[kFields][L::kWidth];
  Arrays arrays;
};

template <class L>
void fillTail(const Box2Arrays& b, std::size_t i, std::size_t last,
              PaddedTail<L, Box2Arrays, 6>& t) {
  const double* src[6] = {b.cx, b.cy, b.ux, b.uy, b.hx, b.hy};
  for (std::size_t f = 0; f < 6; ++f) {
    for (std::size_t k = 0; k < L::kWidth; ++k) {
      t.values[f][k] = src[f][i + k < last ? i + k : last - 1];
    }
  }
  t.arrays = {t.values[0], t.values[1], t.values[2], t.values[3], t.values[4], t.values[5]};
}

template <class L>
void fillTail(const Box3Arrays& b, std::size_t i, std::size_t last,
              PaddedTail<L, Box3Arrays, 15>& t) {
  const double* src[15] = {b.cx,   b.cy,   b.cz,   b.r[0], b.r[1], b.r[2], b.r[3], b.r[4],
                           b.r[5], b.r[6], b.r[7], b.r[8], b.hx,   b.hy,   b.hz};
  for (std::size_t f = 0; f < 15; ++f) {
    for (std::size_t k = 0; k < L::kWidth; ++k) {
      t.values[f][k] = src[f][i + k < last ? i + k : last - 1];
    }
  }
  t.arrays.cx = t.values[0];
  t.arrays.cy = t.values[1];
  t.arrays.cz = t.values[2];
  for (std::size_t m = 0; m < 9; ++m) t.arrays.r[m] = t.values[3 + m];
  t.arrays.hx = t.values[12];
  t.arrays.hy = t.values[13];
  t.arrays.hz = t.values[14];
}

template <class L>
void runOverlap2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                 std::uint8_t* hit) {
  // The loop works on local copies: a store through `hit` (or `out` below) may alias anything the
  // references reach, which would reload every pointer and query field after each store.
  const Box2One a_copy = a;
  const Box2Arrays b_copy = b;
  std::size_t i = first;
  for (; i + L::kWidth <= last; i += L::kWidth) {
    storeHits(hit + i, separated2<L>(a_copy, b_copy, i));
  }
  if (i == last) return;
  PaddedTail<L, Box2Arrays, 6> t;
  fillTail<L>(b, i, last, t);
  std::uint8_t h[L::kWidth];
  storeHits(h, separated2<L>(a, t.arrays, 0));
  for (std::size_t k = 0; i + k < last; ++k) hit[i + k] = h[k];
}

template <class L>
void runCollide2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                 const Sat2Out& out) {
  const Box2One a_copy = a;
  const Box2Arrays b_copy = b;
  const Sat2Out out_copy = out;
  std::size_t i = first;
  for (; i + L::kWidth <= last; i += L::kWidth) collide2<L>(a_copy, b_copy, i, out_copy, i);
  if (i == last) return;
  PaddedTail<L, Box2Arrays, 6> t;
  fillTail<L>(b, i, last, t);
  double sep[L::kWidth], nx[L::kWidth], ny[L::kWidth];
  collide2<L>(a, t.arrays, 0, Sat2Out{sep, nx, ny}, 0);
  for (std::size_t k = 0; i + k < last; ++k) {
    out.separation[i + k] = sep[k];
    out.nx[i + k] = nx[k];
    out.ny[i + k] = ny[k];
  }
}

template <class L>
void runOverlap3(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                 std::uint8_t* hit) {
  std::size_t i = first;
  for (; i + L::kWidth <= last; i += L::kWidth) storeHits(hit + i, separated3<L>(a, b, i));
  if (i == last) return;
  PaddedTail<L, Box3Arrays, 15> t;
  fillTail<L>(b, i, last, t);
  std::uint8_t h[L::kWidth];
  storeHits(h, separated3<L>(a, t.arrays, 0));
  for (std::size_t k = 0; i + k < last; ++k) hit[i + k] = h[k];
}

template <class L>
void runSeparation3(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                    double* separation) {
  std::size_t i = first;
  for (; i + L::kWidth <= last; i += L::kWidth) store(separation + i, separation3<L>(a, b, i));
  if (i == last) return;
  PaddedTail<L, Box3Arrays, 15> t;
  fillTail<L>(b, i, last, t);
  double sep[L::kWidth];
  store(sep, separation3<L>(a, t.arrays, 0));
  for (std::size_t k = 0; i + k < last; ++k) separation[i + k] = sep[k];
}

}  // namespace
}  // namespace cardemo::batch_detail

#undef CARDEMO_BATCH_INLINE
