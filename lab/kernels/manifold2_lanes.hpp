#pragma once
/// Internal to the batch kernels: manifoldObb2 (manifold2.cpp) over a lane type, several pairs at
/// a time and without a branch, giving the scalar function's results bit for bit.
//
// Included after batch_kernels.hpp by batch_avx2.cpp and batch_avx512.cpp only (the portable path
// calls the scalar function). Every arithmetic operation of manifoldObb2 appears here in the same
// order on the same operands, so every value has the same bits. Each choice the scalar code makes
// by branching (early out, reference face, flip, incident face, corners, clipping, which points are
// kept) is made per lane with masks, and both sides are computed. Lanes that the scalar code would
// have left early compute values that are then replaced (a clip's division may be 0/0 there).
//
// Choices are carried as masks combined with bitwise logic rather than blends, and a
// multiplication by a sign of +-1 (exact: it only sets the sign bit) is a masked sign flip: a
// blend for each choice and a multiplication for each sign made the kernel about a third slower.
// Beyond batch_kernels.hpp's lane interface it needs, on masks, ^ and andNot(a, b) = b where a is
// not set; negateWhere(m, x); onlyWhere(m, x) (x where m is set, else +0) and onlyWhereNot(m, x);
// flipSign(x, sign_bits); storeInt32(int32_t*, L).

#include "lab/kernels/batch_kernels.hpp"

// batch_kernels.hpp's attribute, for the same reason: inlined into the driver loop.
#define CARDEMO_MANIFOLD_INLINE [[gnu::always_inline]] inline

namespace cardemo::batch_detail {
namespace {

// manifold2.cpp's firstLargest over four values (faces k .. k + 3): the largest, and the index
// as two bits (high: the pair of k + 2 and k + 3 won; low: the later of the winning pair won).
template <class L>
struct BestFace {
  L value;
  typename L::Mask high, low;
};

template <class L>
CARDEMO_MANIFOLD_INLINE BestFace<L> firstLargestOfFour(const L& v0, const L& v1, const L& v2,
                                                       const L& v3) {
  // `later` wins only where strictly larger, as in the scalar tree.
  const typename L::Mask m01 = gt(v1, v0), m23 = gt(v3, v2);
  const L w01 = select(m01, v1, v0), w23 = select(m23, v3, v2);
  const typename L::Mask top = gt(w23, w01);
  return {select(top, w23, w01), top, (top & m23) | andNot(top, m01)};
}

// One coordinate pair of a point in the reference box's frame, split by the reference face's axis:
// `along` its normal and `across` the face.
template <class L>
struct FacePoint {
  L along, across, id;
};

// clipSegment of manifold2.cpp against the side plane sign * across <= side, the sign given as
// sign bits (-0.0 in the lanes where it is -1, else +0.0). Returns the lanes where nothing is left.
template <class L>
CARDEMO_MANIFOLD_INLINE typename L::Mask clipLanes(FacePoint<L>& s0, FacePoint<L>& s1,
                                                   const L& sign_bits, const L& side,
                                                   double clip_id) {
  const L d0 = flipSign(s0.across, sign_bits) - side;
  const L d1 = flipSign(s1.across, sign_bits) - side;
  const L zero = L::splat(0.0);
  const typename L::Mask out0 = gt(d0, zero), out1 = gt(d1, zero);
  const L r = d0 / (d0 - d1);
  const L along = s0.along + r * (s1.along - s0.along);
  const L across = s0.across + r * (s1.across - s0.across);
  const L id = L::splat(clip_id);
  // Where exactly one end is outside, that end becomes the cut; where both are, the lane is empty
  // and its values no longer matter.
  s0 = {select(out0, along, s0.along), select(out0, across, s0.across),
        onlyWhere(out0, id) + onlyWhereNot(out0, s0.id)};
  s1 = {select(out1, along, s1.along), select(out1, across, s1.across),
        onlyWhere(out1, id) + onlyWhereNot(out1, s1.id)};
  return out0 & out1;
}

// The reference face of one lane group, and the pose seen from it.
template <class L>
struct ReferenceLanes {
  typename L::Mask empty;     // separated by more than max_separation: no manifold
  typename L::Mask flip;      // B holds the reference face
  typename L::Mask on_y;      // the face's normal is its box's y axis (face k odd)
  typename L::Mask negative;  // the face's normal points along minus that axis (k >= 2)
  L face;                     // 0-7
  L t0, t1;                   // the incident box's centre in the reference frame
  L c, sr;                    // its axis there
};

// Pose, the eight face separations and the reference face (pairPose, faceSeparations and
// chooseReference with no previous face).
template <class L>
CARDEMO_MANIFOLD_INLINE ReferenceLanes<L> referenceFace(const Box2Arrays& a, const Box2Arrays& b,
                                                        const ManifoldParams& settings,
                                                        std::size_t i) {
  using Mask = typename L::Mask;
  const L ax = L::load(a.ux + i), ay = L::load(a.uy + i);
  const L ahx = L::load(a.hx + i), ahy = L::load(a.hy + i);
  const L bx = L::load(b.ux + i), by = L::load(b.uy + i);
  const L bhx = L::load(b.hx + i), bhy = L::load(b.hy + i);
  const L dx = L::load(b.cx + i) - L::load(a.cx + i);
  const L dy = L::load(b.cy + i) - L::load(a.cy + i);
  const L ta0 = ax * dx + ay * dy;
  const L ta1 = ax * dy - ay * dx;
  const L tb0 = -(bx * dx + by * dy);
  const L tb1 = -(bx * dy - by * dx);
  const L c = ax * bx + ay * by;
  const L s = ax * by - ay * bx;

  const L ac = abs(c), as = abs(s);
  const L rb0 = bhx * ac + bhy * as, rb1 = bhx * as + bhy * ac;
  const L ra0 = ahx * ac + ahy * as, ra1 = ahx * as + ahy * ac;
  const BestFace<L> best_a =
      firstLargestOfFour(ta0 - ahx - rb0, ta1 - ahy - rb1, -ta0 - ahx - rb0, -ta1 - ahy - rb1);
  const BestFace<L> best_b =
      firstLargestOfFour(tb0 - bhx - ra0, tb1 - bhy - ra1, -tb0 - bhx - ra0, -tb1 - bhy - ra1);
  // The largest separation exceeds max_separation iff one of the two halves' largest does.
  const L max_separation = L::splat(settings.max_separation);
  ReferenceLanes<L> r;
  r.empty = gt(best_a.value, max_separation) | gt(best_b.value, max_separation);
  const L margin_a = L::splat(settings.relative) * abs(best_a.value) + L::splat(settings.absolute);
  const Mask flip = gt(best_b.value, best_a.value + margin_a);
  r.flip = flip;
  r.negative = (flip & best_b.high) | andNot(flip, best_a.high);
  r.on_y = (flip & best_b.low) | andNot(flip, best_a.low);
  r.face = onlyWhere(flip, L::splat(4.0)) + onlyWhere(r.negative, L::splat(2.0)) +
           onlyWhere(r.on_y, L::splat(1.0));
  r.t0 = select(flip, tb0, ta0);
  r.t1 = select(flip, tb1, ta1);
  r.c = c;
  r.sr = negateWhere(flip, s);
  return r;
}

// From the reference face on: incident edge, the two clips, the points; writes entry group i.
template <class L>
CARDEMO_MANIFOLD_INLINE void clipAndWrite(const Box2Arrays& a, const Box2Arrays& b,
                                          const ManifoldParams& settings, std::size_t i,
                                          const ReferenceLanes<L>& r, const Manifold2Out& out) {
  using Mask = typename L::Mask;
  const L zero = L::splat(0.0), one = L::splat(1.0);
  const Mask flip = r.flip, on_y = r.on_y, negative = r.negative;
  // The reference and incident boxes.
  const L rcx = select(flip, L::load(b.cx + i), L::load(a.cx + i));
  const L rcy = select(flip, L::load(b.cy + i), L::load(a.cy + i));
  const L rux = select(flip, L::load(b.ux + i), L::load(a.ux + i));
  const L ruy = select(flip, L::load(b.uy + i), L::load(a.uy + i));
  const L ahx = L::load(a.hx + i), ahy = L::load(a.hy + i);
  const L bhx = L::load(b.hx + i), bhy = L::load(b.hy + i);
  const L rhx = select(flip, bhx, ahx), rhy = select(flip, bhy, ahy);
  const L ihx = select(flip, ahx, bhx), ihy = select(flip, ahy, bhy);

  // Incident face j: the first smallest of (du, dv, -du, -dv), u = (c, sr), v = (-sr, c), each
  // taken along the reference normal (sign times its axis's coordinate).
  const L c = r.c, sr = r.sr, minus_sr = -r.sr;
  const L du = negateWhere(negative, select(on_y, sr, c));
  const L dv = negateWhere(negative, select(on_y, c, minus_sr));
  // -dv < -du iff dv > du (negation is exact and reverses the order).
  const Mask m01 = lt(dv, du), m23 = gt(dv, du);
  const Mask top = lt(-select(m23, dv, du), select(m01, dv, du));
  const Mask j_high = top, j_low = (top & m23) | andNot(top, m01);
  // Corner j has sx = - iff j >= 2 and sy = - iff j is 0 or 3; corner j + 1 (mod 4) has sx = -
  // iff j is 1 or 2 and sy = - iff j >= 2.
  const Mask mixed = j_high ^ j_low;
  const L id0 = onlyWhere(j_high, L::splat(2.0)) + onlyWhere(j_low, one);
  const L id1 = onlyWhere(mixed, L::splat(2.0)) + onlyWhereNot(j_low, one);

  const L ex0 = c * ihx, ex1 = sr * ihx;
  const L ey0 = minus_sr * ihy, ey1 = c * ihy;
  const L t_along = select(on_y, r.t1, r.t0), t_across = select(on_y, r.t0, r.t1);
  const L ex_along = select(on_y, ex1, ex0), ex_across = select(on_y, ex0, ex1);
  const L ey_along = select(on_y, ey1, ey0), ey_across = select(on_y, ey0, ey1);
  // t + sx ex + sy ey, coordinate by coordinate, each sign of +-1 applied as sign bits.
  const L minus_zero = L::splat(-0.0);
  const L high_bits = onlyWhere(j_high, minus_zero);
  const L mixed_bits = onlyWhere(mixed, minus_zero), unmixed_bits = onlyWhereNot(mixed, minus_zero);
  FacePoint<L> p0{t_along + flipSign(ex_along, high_bits) + flipSign(ey_along, unmixed_bits),
                  t_across + flipSign(ex_across, high_bits) + flipSign(ey_across, unmixed_bits),
                  id0};
  FacePoint<L> p1{t_along + flipSign(ex_along, mixed_bits) + flipSign(ey_along, high_bits),
                  t_across + flipSign(ex_across, mixed_bits) + flipSign(ey_across, high_bits), id1};

  // The side planes: -tangent_sign then tangent_sign, where tangent_sign is sign for an x face
  // and -sign for a y face: negative for the second clip iff on_y differs from negative.
  const Mask second_negative = on_y ^ negative;
  const L side = select(on_y, rhx, rhy);
  Mask empty = r.empty | clipLanes(p0, p1, onlyWhereNot(second_negative, minus_zero), side, 4.0);
  empty = empty | clipLanes(p0, p1, onlyWhere(second_negative, minus_zero), side, 5.0);

  const L offset = select(on_y, rhy, rhx);
  // n = sign (u or its perpendicular, as the face's axis), then -n where B is the reference.
  const Mask normal_flip = negative ^ flip;
  const L minus_ruy = -ruy;
  store(out.nx + i, select(empty, one, negateWhere(normal_flip, select(on_y, minus_ruy, rux))));
  store(out.ny + i, select(empty, zero, negateWhere(normal_flip, select(on_y, rux, ruy))));
  storeInt32(out.reference_face + i, select(empty, L::splat(-1.0), r.face));

  // Each end's separation, and its point on B's surface (moved onto B's face where B is the
  // reference).
  const L feature_base = L::splat(8.0) * r.face;
  struct Point {
    L x, y, separation, feature;
  };
  const L negative_bits = onlyWhere(negative, minus_zero);
  const auto point = [&](const FacePoint<L>& p) {
    const L sep = flipSign(p.along, negative_bits) - offset;
    const L along = select(flip, p.along - flipSign(sep, negative_bits), p.along);
    const L q0 = select(on_y, p.across, along), q1 = select(on_y, along, p.across);
    return Point{rcx + rux * q0 + minus_ruy * q1, rcy + ruy * q0 + rux * q1, sep,
                 feature_base + p.id};
  };
  const Point e0 = point(p0), e1 = point(p1);
  // A point farther than max_separation is dropped, and the next one moves up.
  const L max_separation = L::splat(settings.max_separation);
  const Mask drop0 = gt(e0.separation, max_separation);
  const Mask drop1 = gt(e1.separation, max_separation);
  const L count = onlyWhereNot(drop0, one) + onlyWhereNot(drop1, one);
  storeInt32(out.count + i, onlyWhereNot(empty, count));
  store(out.p0x + i, select(drop0, e1.x, e0.x));
  store(out.p0y + i, select(drop0, e1.y, e0.y));
  store(out.separation0 + i, select(drop0, e1.separation, e0.separation));
  storeInt32(out.feature0 + i, select(drop0, e1.feature, e0.feature));
  store(out.p1x + i, e1.x);
  store(out.p1y + i, e1.y);
  store(out.separation1 + i, e1.separation);
  storeInt32(out.feature1 + i, e1.feature);
}

// Pairs [first, last), a whole number of lane groups.
template <class L>
[[gnu::flatten]] void runManifold2(const Box2Arrays& a, const Box2Arrays& b,
                                   const ManifoldParams& settings, std::size_t first,
                                   std::size_t last, const Manifold2Out& out) {
  for (std::size_t i = first; i + L::kWidth <= last; i += L::kWidth) {
    clipAndWrite<L>(a, b, settings, i, referenceFace<L>(a, b, settings, i), out);
  }
}

}  // namespace
}  // namespace cardemo::batch_detail

#undef CARDEMO_MANIFOLD_INLINE
