#pragma once
/// Internal to the batch kernels: each kernel written once over a "lane" type, so the portable
/// build (a lane is one double), AVX2 (four doubles) and AVX-512F (eight) run the same IEEE
/// operations in the same order and give bit-identical results.
///
/// A lane type L provides: L::kWidth, L::Mask, L::load(const double*), L::splat(double),
/// + - * / and unary -, abs, sqrt, fma (correctly rounded a*b+c), gt, lt, mask | and &,
/// select(mask, if_true, if_false), store(double*, L), storeHits(uint8_t*, separated mask) and
/// allOf(mask) (true when every lane is set; the 3D filter branches on it); a type wider than one
/// lane also laneBits(mask) (bit l set where lane l is).
//
// Included by exactly three translation units, batch_portable.cpp, batch_avx2.cpp (compiled with
// -mavx2 -mfma) and batch_avx512.cpp (-mavx512f). Everything here has internal linkage, so the
// linker can never substitute one instantiation for another. Multiplications and additions are
// written out separately and -ffp-contract=off forbids fusing them; the only fused operations are
// the explicit fma calls of the 3D edge axes, which are correctly rounded on every path.

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "lab/kernels/batch_entry.hpp"
#include "lab/kernels/box_fields.hpp"
#include "lab/kernels/filter_run.hpp"

// Every kernel is inlined into its driver loop, so the query box's broadcast values are loaded
// once per call rather than once per lane group (GCC and Clang both honour the attribute).
#define CARDEMO_BATCH_INLINE [[gnu::always_inline]] inline

namespace cardemo::batch_detail {
namespace {

// Calls f(std::integral_constant<int, K>{}) for K = 0, ..., N - 1. The 3D kernels index arrays of
// lanes by axis; with runtime loop indices GCC at -O2 keeps those arrays on the stack and loops
// over them, with compile-time indices (and the 3D drivers flattened, so that these lambdas are
// inlined too) every lane is a named value the compiler can keep in a register.
template <class F, int... K>
CARDEMO_BATCH_INLINE void staticForEach(const F& f, std::integer_sequence<int, K...>) {
  (f(std::integral_constant<int, K>{}), ...);
}

template <int N, class F>
CARDEMO_BATCH_INLINE void staticFor(const F& f) {
  staticForEach(f, std::make_integer_sequence<int, N>{});
}

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
inline constexpr double kMinAxisLength2 = 0x1p-960;

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
  L t[3];        // d in A's frame: a_k . d
  L R[3][3];     // a_k . b_j
  L absR[3][3];  // |a_k . b_j|
  L face[6];     // gaps on A's faces 0-2 and B's faces 0-2
};

template <class L>
CARDEMO_BATCH_INLINE Pair3Lanes<L> pair3(const Box3One& a, const Box3Arrays& b, std::size_t i) {
  Pair3Lanes<L> p;
  p.d = {L::load(b.cx + i) - L::splat(a.cx), L::load(b.cy + i) - L::splat(a.cy),
         L::load(b.cz + i) - L::splat(a.cz)};
  for (std::size_t j = 0; j < 3; ++j) {
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
  staticFor<9>([&p](auto e) {
    constexpr int k = decltype(e)::value / 3, j = decltype(e)::value % 3;
    p.R[k][j] = dot(p.a[k], p.b[j]);
    p.absR[k][j] = abs(p.R[k][j]);
  });
  staticFor<3>([&p](auto kc) {
    constexpr int k = decltype(kc)::value;
    const L rb = p.absR[k][0] * p.hb[0] + p.absR[k][1] * p.hb[1] + p.absR[k][2] * p.hb[2];
    p.t[k] = dot(p.a[k], p.d);
    p.face[k] = abs(p.t[k]) - p.ha[k] - rb;
  });
  staticFor<3>([&p](auto jc) {
    constexpr int j = decltype(jc)::value;
    const L ra = p.absR[0][j] * p.ha[0] + p.absR[1][j] * p.ha[1] + p.absR[2][j] * p.ha[2];
    p.face[3 + j] = abs(dot(p.b[j], p.d)) - p.hb[j] - ra;
  });
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
  staticFor<5>([&](auto k) { out = out | gt(p.face[decltype(k)::value + 1], zero); });
  staticFor<9>([&](auto e) {
    const EdgeGap<L> g = edgeGap(p, decltype(e)::value / 3, decltype(e)::value % 3);
    out = out | (g.valid & gt(g.gap, zero));
  });
  return out;
}

template <class L>
CARDEMO_BATCH_INLINE L separation3(const Box3One& a, const Box3Arrays& b, std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  L best = p.face[0];
  staticFor<5>([&](auto kc) {
    const L& face = p.face[decltype(kc)::value + 1];
    best = select(gt(face, best), face, best);
  });
  staticFor<9>([&](auto e) {
    const EdgeGap<L> g = edgeGap(p, decltype(e)::value / 3, decltype(e)::value % 3);
    const L gap = g.gap / sqrt(g.length2);
    best = select(g.valid & gt(gap, best), gap, best);
  });
  return best;
}

// ---------------------------------------------------------------------------------------------
// 3D, fast: the A-frame filter (lab/README.md, "The 3D double kernels"). The edge axis a_i x b_j in
// A's frame is e_i x (A^T b_j), whose gap (Gottschalk et al. 1996) needs only entries of R = A^T B
// and of t = A^T d, both already formed for the face axes: about a dozen operations per axis
// instead of fifty. Its error against the gap on the stored columns' exact cross product, which
// the accurate kernel computes to a few ulps, is bounded (Box3One::edge_gap_error): a lane is
// decided when every gap clears that bound, or a face or edge gap certainly separates; the rest
// (near touching, or edges too close to parallel for the A-frame form) go to the accurate kernel,
// so every verdict is the accurate kernel's.

// The accurate kernel skips an edge axis whose squared length is at most kMinAxisLength2; this is
// the next double up, so lt(length2, it) is exactly that skip.
inline constexpr double kSkippedBelow = 0x1.0000000000001p-960;
// Separations from the filter are within kSeparationTolerance times the pair's scale of the
// accurate kernel's (Box3One::min_edge_length2 is set for it).
inline constexpr double kSeparationTolerance = 0x1p-40;

// The pair's scale: |d|_1 plus every half extent; it bounds |d|, each projected radius and, so,
// each gap on a unit axis.
template <class L>
CARDEMO_BATCH_INLINE L scale3(const Pair3Lanes<L>& p) {
  return abs(p.d.x) + abs(p.d.y) + abs(p.d.z) + (p.ha[0] + p.ha[1] + p.ha[2]) +
         (p.hb[0] + p.hb[1] + p.hb[2]);
}

// Edge axis a_i x b_j in A's frame: its gap times its length, and its squared length.
template <class L>
struct FastEdge {
  L gap;
  L length2;
};

template <class L>
CARDEMO_BATCH_INLINE FastEdge<L> fastEdge(const Pair3Lanes<L>& p, int i, int j) {
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  // e_i x r_j = r_{i1 j} e_{i2} - r_{i2 j} e_{i1}; its dot products with A's other axes are R
  // entries of row i2 and i1, with B's other axes entries of row i (B's columns j x j1 = j2).
  const L along = p.t[i2] * p.R[i1][j] - p.t[i1] * p.R[i2][j];
  const L ra = p.ha[i1] * p.absR[i2][j] + p.ha[i2] * p.absR[i1][j];
  const L rb = p.hb[j1] * p.absR[i][j2] + p.hb[j2] * p.absR[i][j1];
  return {abs(along) - ra - rb, p.R[i1][j] * p.R[i1][j] + p.R[i2][j] * p.R[i2][j]};
}

// The lanes where the accurate kernel skips edge axis (i, j): its cross product is exactly zero
// (exactly parallel edges; cars on flat ground share their vertical axis). Same operations as
// edgeGap, so the same decision.
template <class L>
CARDEMO_BATCH_INLINE typename L::Mask skippedEdge(const Pair3Lanes<L>& p, int i, int j) {
  const V3<L> n = accurateCross(p.a[i], p.b[j]);
  return lt(dot(n, n), L::splat(kSkippedBelow));
}

// Marks as sure the lanes of every edge axis that the accurate kernel skips, for the axes where
// some lane is not sure yet (ignoring lanes in `done`); returns the lanes sure on all nine.
template <class L>
CARDEMO_BATCH_INLINE typename L::Mask certifySkipped(const Pair3Lanes<L>& p,
                                                     typename L::Mask (&sure)[9],
                                                     typename L::Mask done) {
  typename L::Mask all = sure[0];
  staticFor<9>([&](auto ec) {
    constexpr int e = decltype(ec)::value;
    if (!allOf(sure[e] | done)) sure[e] = sure[e] | skippedEdge(p, e / 3, e % 3);
    all = e == 0 ? sure[0] : all & sure[e];
  });
  return all;
}

// mask ? x : y, lane by lane, for masks.
template <class L>
CARDEMO_BATCH_INLINE typename L::Mask selectMask(typename L::Mask m, typename L::Mask x,
                                                 typename L::Mask y) {
  const L one = L::splat(1.0), zero = L::splat(0.0);
  return gt(select(m, select(x, one, zero), select(y, one, zero)), L::splat(0.5));
}

template <class L>
CARDEMO_BATCH_INLINE typename L::Mask separated3Filtered(const Box3One& a, const Box3Arrays& b,
                                                         std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  const L zero = L::splat(0.0);
  typename L::Mask separated = gt(p.face[0], zero);
  staticFor<5>([&](auto k) { separated = separated | gt(p.face[decltype(k)::value + 1], zero); });
  // A face gap is the accurate kernel's own, so a lane it separates is decided. One pair at a time
  // (the portable path) that is an early out for about half the pairs; across four or eight
  // lanes it seldom holds for all, and the branch cost more than it saved.
  if constexpr (L::kWidth == 1) {
    if (allOf(separated)) return separated;
  }
  const L bound = L::splat(a.edge_gap_error) * scale3(p);
  // An edge gap beyond the bound has the accurate gap's sign: above it, certainly separated;
  // below minus it, certainly not separated on that axis.
  typename L::Mask sure[9];
  typename L::Mask all_sure;
  staticFor<9>([&](auto ec) {
    constexpr int e = decltype(ec)::value;
    const L gap = fastEdge(p, e / 3, e % 3).gap;
    separated = separated | gt(gap, bound);
    sure[e] = gt(abs(gap), bound);
    all_sure = e == 0 ? sure[0] : all_sure & sure[e];
  });
  if (allOf(separated | all_sure)) return separated;
  all_sure = certifySkipped(p, sure, separated);
  const typename L::Mask decided = separated | all_sure;
  if (allOf(decided)) return separated;
  return selectMask<L>(decided, separated, separated3<L>(a, b, i));
}

// A candidate separation gap / sqrt(length2), carried as gap, length2 and gap |gap|.
template <class L>
struct Candidate {
  L gap, length2, square;
};

// The larger of two candidates, compared without a root: z -> z|z| is increasing, so
// x.gap / sqrt(x.length2) > y.gap / sqrt(y.length2) iff x.square y.length2 > y.square x.length2.
template <class L>
CARDEMO_BATCH_INLINE Candidate<L> larger(const Candidate<L>& x, const Candidate<L>& y) {
  const typename L::Mask wins = gt(x.square * y.length2, y.square * x.length2);
  return {select(wins, x.gap, y.gap), select(wins, x.length2, y.length2),
          select(wins, x.square, y.square)};
}

// The A-frame separations of lane group i, and the lanes where they are the accurate kernel's to
// within kSeparationTolerance times the scale with its sign; the other lanes need that kernel.
template <class L>
struct FilteredSeparation {
  L value;
  typename L::Mask decided;
};

// separation3Fast's rare path (some lane has an edge pair too close to parallel for the A-frame
// form): the sure lanes of every edge axis, and certifySkipped, on the pair formed again from
// memory. Out of line, so that the common path keeps neither B's axes nor nine masks live to its
// end (on AVX-512 they were many of its register spills).
template <class L>
[[gnu::noinline]] typename L::Mask certifyFromMemory(const Box3One& a, const Box3Arrays& b,
                                                     std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  const L floor = L::splat(a.min_edge_length2);
  typename L::Mask sure[9];
  staticFor<9>([&](auto ec) {
    constexpr int e = decltype(ec)::value;
    sure[e] = gt(fastEdge(p, e / 3, e % 3).length2, floor);
  });
  return certifySkipped(p, sure, lt(L::splat(1.0), L::splat(0.0)));
}

template <class L>
CARDEMO_BATCH_INLINE FilteredSeparation<L> separation3Fast(const Box3One& a, const Box3Arrays& b,
                                                           std::size_t i) {
  const Pair3Lanes<L> p = pair3<L>(a, b, i);
  // The largest of the face gaps and of gap / sqrt(length2) over the edges that are well enough
  // conditioned (length2 above the floor, where the normalised error is within
  // kSeparationTolerance times the scale); the others enter as -infinity and never win. Reduced
  // as a tournament, so the dependency chain is four comparisons deep rather than fifteen; one
  // root and one division at the end. Candidate c0 is the faces, c1-c9 the edges; the pairs
  // (c0, c1), (c2, c3), ... are decided as soon as both are formed, and so are the later rounds,
  // so that few candidates are live at once.
  const L one = L::splat(1.0), never = L::splat(-__builtin_inf());
  const L face01 = select(gt(p.face[1], p.face[0]), p.face[1], p.face[0]);
  const L face23 = select(gt(p.face[3], p.face[2]), p.face[3], p.face[2]);
  const L face45 = select(gt(p.face[5], p.face[4]), p.face[5], p.face[4]);
  const L face03 = select(gt(face23, face01), face23, face01);
  const L face = select(gt(face45, face03), face45, face03);
  const L floor = L::splat(a.min_edge_length2);
  Candidate<L> held = {face, one, face * abs(face)};  // c_{2k}, waiting for c_{2k+1}
  Candidate<L> round1[2];                             // (c0, c1) and (c4, c5), for round 2
  Candidate<L> round2;                                // (c0..c3), for round 3
  Candidate<L> best;                                  // c0..c7
  typename L::Mask all_sure;
  staticFor<9>([&](auto ec) {
    constexpr int e = decltype(ec)::value;
    const FastEdge<L> f = fastEdge(p, e / 3, e % 3);
    const typename L::Mask sure = gt(f.length2, floor);
    const Candidate<L> c{f.gap, select(sure, f.length2, one),
                         select(sure, f.gap * abs(f.gap), never)};
    all_sure = e == 0 ? sure : all_sure & sure;
    if constexpr (e % 2 == 1) {
      held = c;  // c_{e+1}, e + 1 even
    } else {
      const Candidate<L> pair = larger(held, c);  // round 1: (c_e, c_{e+1})
      if constexpr (e == 0 || e == 4) {
        round1[e / 4] = pair;
      } else if constexpr (e == 2) {
        round2 = larger(round1[0], pair);
      } else if constexpr (e == 6) {
        best = larger(round2, larger(round1[1], pair));
      } else {
        best = larger(best, pair);  // e == 8: (c8, c9) joins last
      }
    }
  });
  const L value = best.gap / sqrt(best.length2);
  // Near zero the sign (the verdict) must be the accurate kernel's: leave those lanes to it.
  const typename L::Mask clear = gt(abs(value), L::splat(2.0 * kSeparationTolerance) * scale3(p));
  if (allOf(all_sure)) [[likely]]
    return {value, all_sure & clear};
  return {value, certifyFromMemory<L>(a, b, i) & clear};
}

template <class L>
CARDEMO_BATCH_INLINE L separation3Filtered(const Box3One& a, const Box3Arrays& b, std::size_t i) {
  const FilteredSeparation<L> f = separation3Fast<L>(a, b, i);
  if (allOf(f.decided)) return f.value;
  return select(f.decided, f.value, separation3<L>(a, b, i));
}

// ---------------------------------------------------------------------------------------------
// Drivers: whole lane groups, then a tail group padded with copies of the last box.

template <class L, class Arrays, std::size_t kFields>
struct PaddedTail {
  double values[kFields][L::kWidth];
  Arrays arrays;
};

template <class L, class Arrays, std::size_t kFields>
void fillTail(const Arrays& b, std::size_t i, std::size_t last, PaddedTail<L, Arrays, kFields>& t) {
  const auto source = fieldsOf(b);
  for (std::size_t f = 0; f < kFields; ++f) {
    for (std::size_t k = 0; k < L::kWidth; ++k) {
      t.values[f][k] = source.field[f][i + k < last ? i + k : last - 1];
    }
  }
  t.arrays = arraysOf(t.values);
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
  if constexpr (L::kWidth == 8) {
    // A lane group reads one cache line of each field: the six lines eight groups ahead are
    // requested now. Once the boxes no longer fit in L2 this hides more of the wait than the
    // hardware prefetcher does on its own.
    constexpr std::size_t kAhead = 8 * L::kWidth;
    for (; i + L::kWidth <= last; i += L::kWidth) {
      const double* const fields[6] = {b_copy.cx, b_copy.cy, b_copy.ux,
                                       b_copy.uy, b_copy.hx, b_copy.hy};
      for (const double* field : fields) __builtin_prefetch(field + i + kAhead);
      collide2<L>(a_copy, b_copy, i, out_copy, i);
    }
  }
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
[[gnu::flatten]] void runOverlap3(const Box3One& a, const Box3Arrays& b, std::size_t first,
                                  std::size_t last, std::uint8_t* hit) {
  std::size_t i = first;
  for (; i + L::kWidth <= last; i += L::kWidth) {
    storeHits(hit + i, separated3Filtered<L>(a, b, i));
  }
  if (i == last) return;
  PaddedTail<L, Box3Arrays, 15> t;
  fillTail<L>(b, i, last, t);
  std::uint8_t h[L::kWidth];
  storeHits(h, separated3Filtered<L>(a, t.arrays, 0));
  for (std::size_t k = 0; i + k < last; ++k) hit[i + k] = h[k];
}

// runSeparation3's open boxes, decided by the accurate kernel. Out of line: inlined into the loop
// (which is flattened), its code took registers from the filter, which spilled more.
template <class L>
[[gnu::noinline]] void decideOpenSeparations(const Box3One& a, const Box3Fields& source,
                                             const std::size_t* pending, std::size_t count,
                                             double* separation) {
  decideOpenBoxes<L::kWidth>(source.field, pending, count, separation,
                             [&a](const double(&f)[15][L::kWidth], double* group_out) {
                               store(group_out, separation3<L>(a, arraysOf(f), 0));
                             });
}

// On more than one lane, the boxes the filter leaves undecided (separations within about 2^-39 of
// the pair's scale of zero: resting contacts) go on one by one, as in the boolean pre-filters
// (filter_run.hpp), so the accurate kernel runs on them alone rather than on each of their lane
// groups (lab/README.md, "The float pre-filters").
template <class L>
[[gnu::flatten]] void runSeparation3(const Box3One& a, const Box3Arrays& b, std::size_t first,
                                     std::size_t last, double* separation) {
  std::size_t i = first;
  if constexpr (L::kWidth == 1) {
    for (; i < last; ++i) store(separation + i, separation3Filtered<L>(a, b, i));
    return;
  } else {
    constexpr std::size_t kPending = 64;
    std::size_t pending[kPending + L::kWidth];
    std::size_t count = 0;
    const Box3Fields source = fieldsOf(b);
    const auto decide_pending = [&] {
      decideOpenSeparations<L>(a, source, pending, count, separation);
      count = 0;
    };
    for (; i + L::kWidth <= last; i += L::kWidth) {
      const FilteredSeparation<L> f = separation3Fast<L>(a, b, i);
      store(separation + i, f.value);
      if (allOf(f.decided)) [[likely]]
        continue;
      for (unsigned open = ~laneBits(f.decided) & ((1u << L::kWidth) - 1u); open != 0;
           open &= open - 1) {
        pending[count++] = i + static_cast<std::size_t>(__builtin_ctz(open));
      }
      if (count >= kPending) decide_pending();
    }
    if (count > 0) decide_pending();
  }
  if (i == last) return;
  PaddedTail<L, Box3Arrays, 15> t;
  fillTail<L>(b, i, last, t);
  double sep[L::kWidth];
  store(sep, separation3Filtered<L>(a, t.arrays, 0));
  for (std::size_t k = 0; i + k < last; ++k) separation[i + k] = sep[k];
}

}  // namespace
}  // namespace cardemo::batch_detail

#undef CARDEMO_BATCH_INLINE
