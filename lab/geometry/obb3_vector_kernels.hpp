#pragma once
/// Internal to obb3_avx2.cpp and obb3_avx512.cpp: overlapObb3's and collideObb3's common case with
/// 256-bit vectors, compiled once per instruction set.
//
// Each 3-vector of obb3.cpp's SSE2 form (two registers there) is one register here, lane 3 unused.
// Lane k does the operations of the scalar formula it stands for, in obb3.cpp's order, so every
// gap is the same bit for bit. The AVX2 build has sixteen vector registers; the AVX-512VL build
// of the same source has thirty-two, so it spills less, and its operations are the same IEEE
// ones, so its bits are too. -ffp-contract=off keeps every product rounded on its own.
//
// Includes nothing but the intrinsics, obb3_lanes.hpp and lanes_avx2.hpp, for the reason given in
// lab/kernels/batch_avx2.cpp; everything here has internal linkage, so the two builds cannot be
// mixed up by the linker.

#include <immintrin.h>

#include "lab/geometry/obb3_lanes.hpp"
#include "lab/kernels/lanes_avx2.hpp"

namespace cardemo::obb3_detail {
namespace {

using batch_detail::largestLane;

// Lane k of next1(u) is lane k + 1 (mod 3) of u, of next2(u) lane k + 2; lane 3 stays.
[[gnu::always_inline]] inline __m256d next1(__m256d u) {
  return _mm256_permute4x64_pd(u, 0b11001001);
}
[[gnu::always_inline]] inline __m256d next2(__m256d u) {
  return _mm256_permute4x64_pd(u, 0b11010010);
}
[[gnu::always_inline]] inline __m256d abs4(__m256d u) {
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), u);
}
[[gnu::always_inline]] inline __m256d splat(double x) {
  return _mm256_set1_pd(x);
}
// Lane 3 set to -infinity, so that it never wins a maximum.
[[gnu::always_inline]] inline __m256d withoutPadding(__m256d u) {
  return _mm256_blend_pd(u, splat(-__builtin_inf()), 0b1000);
}

// obb3.cpp's Pose3 and FastEdges, as registers: lane k of t is a_k . d, lane k of col[j] is
// r_kj = a_k . b_j; lane j of tb is b_j . d and of face_b the gap on B's face j.
struct Lanes {
  __m256d t, tb, col[3], abscol[3], face_a, face_b;
  __m256d gap[3], length2[3];
};

// Lanes 0-2 of x, y and z in turn (lane 3 is y's): two blends, no shuffle.
[[gnu::always_inline]] inline __m256d merge(__m256d x, __m256d y, __m256d z) {
  return _mm256_blend_pd(_mm256_blend_pd(y, x, 0b0001), z, 0b0100);
}

// The rows of a column-major 3x3 matrix m (lane k of row i is m_ik = m[3k + i]), from 128-bit
// loads and unpacks: no arithmetic, so the same values as three gathers, in fewer instructions.
[[gnu::always_inline]] inline void rowsOf(const double* m, __m256d& x, __m256d& y, __m256d& z) {
  const __m256d m0167 = _mm256_loadu2_m128d(m + 6, m);  // m0 m1 | m6 m7
  const __m256d m3434 = _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(m + 3));
  const __m256d m1278 = _mm256_loadu2_m128d(m + 7, m + 1);  // m1 m2 | m7 m8
  const __m256d m4545 = _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(m + 4));
  x = _mm256_unpacklo_pd(m0167, m3434);  // m0 m3 | m6 m3
  y = _mm256_unpackhi_pd(m0167, m3434);  // m1 m4 | m7 m4
  z = _mm256_unpackhi_pd(m1278, m4545);  // m2 m5 | m8 m5
}

[[gnu::always_inline]] inline __m256d broadcast(const double* x) {
  return _mm256_broadcast_sd(x);
}

[[gnu::always_inline]] inline __m256d dotColumns(__m256d x, __m256d y, __m256d z, __m256d u,
                                                 __m256d v, __m256d w) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x, u), _mm256_mul_pd(y, v)),
                       _mm256_mul_pd(z, w));
}

// Every splat is a load of its own (a broadcast from memory), and each 3-vector of lanes is a blend
// of splats or comes from 128-bit loads: no gathers, few shuffles. Written in the order the values
// die, so that they fit in the sixteen registers.
[[gnu::always_inline]] inline Lanes poseAndFaces(const double* a, const double* b) {
  Lanes p;
  const double *ca = a + BoxNumbers::kCenter, *cb = b + BoxNumbers::kCenter;
  const double *ha = a + BoxNumbers::kHalf, *hb = b + BoxNumbers::kHalf;
  const double* rb = b + BoxNumbers::kRotation;
  __m256d ax, ay, az;
  rowsOf(a + BoxNumbers::kRotation, ax, ay, az);
  // d = cB - cA, each component subtracted once per lane: the same bits as the scalar difference.
  const __m256d vdx = _mm256_sub_pd(broadcast(cb), broadcast(ca));
  const __m256d vdy = _mm256_sub_pd(broadcast(cb + 1), broadcast(ca + 1));
  const __m256d vdz = _mm256_sub_pd(broadcast(cb + 2), broadcast(ca + 2));
  p.t = dotColumns(ax, ay, az, vdx, vdy, vdz);
  // B's rows (lane j of bx is b_j's x) as blends of the splats of its entries.
  __m256d bx, by, bz;
  for (std::size_t j = 0; j < 3; ++j) {
    const __m256d sx = broadcast(rb + 3 * j), sy = broadcast(rb + 3 * j + 1),
                  sz = broadcast(rb + 3 * j + 2);
    p.col[j] = dotColumns(ax, ay, az, sx, sy, sz);
    p.abscol[j] = abs4(p.col[j]);
    // Literal immediates: an unoptimised build does not fold a computed one.
    if (j == 0) {
      bx = sx, by = sy, bz = sz;
    } else if (j == 1) {
      bx = _mm256_blend_pd(bx, sx, 0b1010), by = _mm256_blend_pd(by, sy, 0b1010);
      bz = _mm256_blend_pd(bz, sz, 0b1010);
    } else {
      bx = _mm256_blend_pd(bx, sx, 0b0100), by = _mm256_blend_pd(by, sy, 0b0100);
      bz = _mm256_blend_pd(bz, sz, 0b0100);
    }
  }
  p.tb = dotColumns(bx, by, bz, vdx, vdy, vdz);  // lane j: b_j . d
  const __m256d hb0 = broadcast(hb), hb1 = broadcast(hb + 1), hb2 = broadcast(hb + 2);
  const __m256d radius_b =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(p.abscol[0], hb0), _mm256_mul_pd(p.abscol[1], hb1)),
                    _mm256_mul_pd(p.abscol[2], hb2));
  p.face_b = _mm256_sub_pd(abs4(p.tb), merge(hb0, hb1, hb2));
  const __m256d ha0 = broadcast(ha), ha1 = broadcast(ha + 1), ha2 = broadcast(ha + 2);
  p.face_a = _mm256_sub_pd(_mm256_sub_pd(abs4(p.t), merge(ha0, ha1, ha2)), radius_b);
  // B's face j: A's radius sum_k |r_kj| ha_k over lanes k of abscol[j], here lane j of a sum over
  // the rows of |R|, which are the columns transposed (no arithmetic, so the same values).
  const __m256d lo01 = _mm256_unpacklo_pd(p.abscol[0], p.abscol[1]);  // r00 r01 r20 r21
  const __m256d hi01 = _mm256_unpackhi_pd(p.abscol[0], p.abscol[1]);  // r10 r11 .. ..
  const __m256d lo22 = _mm256_unpacklo_pd(p.abscol[2], p.abscol[2]);  // r02 r02 r22 r22
  const __m256d hi22 = _mm256_unpackhi_pd(p.abscol[2], p.abscol[2]);  // r12 r12 .. ..
  const __m256d row_abs[3] = {_mm256_permute2f128_pd(lo01, lo22, 0x20),
                              _mm256_permute2f128_pd(hi01, hi22, 0x20),
                              _mm256_permute2f128_pd(lo01, lo22, 0x31)};
  const __m256d radius_a =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(row_abs[0], ha0), _mm256_mul_pd(row_abs[1], ha1)),
                    _mm256_mul_pd(row_abs[2], ha2));
  p.face_b = _mm256_sub_pd(p.face_b, radius_a);
  return p;
}

// obb3.cpp's fastEdges, column j of R per register.
[[gnu::always_inline]] inline void fastEdges(const double* a, const double* b, Lanes& p) {
  const __m256d t1 = next1(p.t), t2 = next2(p.t);
  const double *ha = a + BoxNumbers::kHalf, *hb = b + BoxNumbers::kHalf;
  const __m256d sha[3] = {broadcast(ha), broadcast(ha + 1), broadcast(ha + 2)};
  const __m256d ha1 = merge(sha[1], sha[2], sha[0]), ha2 = merge(sha[2], sha[0], sha[1]);
  const __m256d shb[3] = {broadcast(hb), broadcast(hb + 1), broadcast(hb + 2)};
  for (int j = 0; j < 3; ++j) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const __m256d r1 = next1(p.col[j]), r2 = next2(p.col[j]);
    const __m256d along = _mm256_sub_pd(_mm256_mul_pd(t2, r1), _mm256_mul_pd(t1, r2));
    const __m256d ra = _mm256_add_pd(_mm256_mul_pd(ha1, abs4(r2)), _mm256_mul_pd(ha2, abs4(r1)));
    const __m256d rb =
        _mm256_add_pd(_mm256_mul_pd(p.abscol[j2], shb[j1]), _mm256_mul_pd(p.abscol[j1], shb[j2]));
    p.gap[j] = _mm256_sub_pd(_mm256_sub_pd(abs4(along), ra), rb);
    p.length2[j] = _mm256_add_pd(_mm256_mul_pd(r1, r1), _mm256_mul_pd(r2, r2));
  }
}

// Root-free edge candidates, one per lane (obb3.cpp's comments on the root-free comparison give
// the comparison, its range and its certificate): gap times axis length, squared axis length, gap
// |gap|, and the axis index (SatResult3::axis_index) as a double.
struct Candidates {
  __m256d gap, length2, square, axis;
};

// Lane by lane the first largest of x then y: y only where its separation is strictly larger.
// `doubtful` gains the lanes where the step is not certain (kCertain).
[[gnu::always_inline]] inline Candidates firstLargest(const Candidates& x, const Candidates& y,
                                                      __m256d& doubtful) {
  const __m256d y_side = _mm256_mul_pd(y.square, x.length2);
  const __m256d x_side = _mm256_mul_pd(x.square, y.length2);
  const __m256d y_wins = _mm256_cmp_pd(y_side, x_side, _CMP_GT_OQ);
  const __m256d margin = _mm256_mul_pd(abs4(y_side), splat(kCertain));
  doubtful = _mm256_or_pd(doubtful,
                          _mm256_cmp_pd(abs4(_mm256_sub_pd(y_side, x_side)), margin, _CMP_NGT_UQ));
  return {_mm256_blendv_pd(x.gap, y.gap, y_wins), _mm256_blendv_pd(x.length2, y.length2, y_wins),
          _mm256_blendv_pd(x.square, y.square, y_wins), _mm256_blendv_pd(x.axis, y.axis, y_wins)};
}

// Lane 1 of every field in lane 0 (the other lanes are not read).
[[gnu::always_inline]] inline Candidates secondLane(const Candidates& c) {
  return {_mm256_permute_pd(c.gap, 0b0101), _mm256_permute_pd(c.length2, 0b0101),
          _mm256_permute_pd(c.square, 0b0101), _mm256_permute_pd(c.axis, 0b0101)};
}

// Lane 2 of every field in lane 0 (the other lanes are not read).
[[gnu::always_inline]] inline Candidates thirdLane(const Candidates& c) {
  const auto high = [](__m256d v) { return _mm256_permute2f128_pd(v, v, 0x01); };
  return {high(c.gap), high(c.length2), high(c.square), high(c.axis)};
}

// The first largest edge candidate, in lane 0, and whether every step was certain. The
// tournament: lane by lane over the columns j (edges (i, 0), (i, 1), (i, 2) in lane i), then
// lanes 0, 1 and 2 in turn. Every step keeps the earlier run of axes unless the later one's
// separation is strictly larger, and every run is consecutive in axis order, so with certain
// steps the first largest axis wins, as in a scan in axis order.
[[gnu::always_inline]] inline Candidates largestEdge(const Lanes& p, bool& certain) {
  Candidates c[3];
  for (int j = 0; j < 3; ++j) {
    c[j] = {p.gap[j], p.length2[j], _mm256_mul_pd(p.gap[j], abs4(p.gap[j])),
            _mm256_setr_pd(6.0 + j, 9.0 + j, 12.0 + j, 12.0 + j)};
  }
  __m256d doubtful_lanes = _mm256_setzero_pd(), doubtful_last = _mm256_setzero_pd();
  const Candidates lanes =
      firstLargest(firstLargest(c[0], c[1], doubtful_lanes), c[2], doubtful_lanes);
  const Candidates best = firstLargest(firstLargest(lanes, secondLane(lanes), doubtful_last),
                                       thirdLane(lanes), doubtful_last);
  certain = ((_mm256_movemask_pd(doubtful_lanes) & 0b0111) |
             (_mm256_movemask_pd(doubtful_last) & 0b0001)) == 0;
  return best;
}

// The largest of the faces' winner (best, best_axis) and the nine edge gaps, root-free: the faces'
// winner enters with length2 = 1 and square best |best|. False, with nothing written, when a step
// is not certain.
[[gnu::always_inline]] inline bool largestRootFree(const Lanes& p, double& best, int& best_axis) {
  bool certain = false;
  const Candidates edge = largestEdge(p, certain);
  const double edge_side = _mm256_cvtsd_f64(edge.square);
  const double face_side = best * __builtin_fabs(best) * _mm256_cvtsd_f64(edge.length2);
  if (!certain || !(__builtin_fabs(edge_side - face_side) > kCertain * __builtin_fabs(edge_side))) {
    return false;
  }
  if (edge_side > face_side) {
    const __m128d length2 = _mm256_castpd256_pd128(edge.length2);
    const __m128d gap = _mm_div_sd(_mm256_castpd256_pd128(edge.gap), _mm_sqrt_sd(length2, length2));
    best = _mm_cvtsd_f64(gap);
    best_axis = static_cast<int>(_mm256_cvtsd_f64(edge.axis));
  }
  return true;
}

// obb3.cpp's largestNormalised: the nine gaps normalised, then picked in axis order.
[[gnu::always_inline]] inline void largestNormalised(const Lanes& p, double& best, int& best_axis) {
  alignas(32) double g[3][4];
  for (int j = 0; j < 3; ++j) {
    _mm256_store_pd(g[j], _mm256_div_pd(p.gap[j], _mm256_sqrt_pd(p.length2[j])));
  }
  for (int e = 0; e < 9; ++e) {
    const double gap = g[e % 3][e / 3];
    const bool larger = gap > best;
    best = larger ? gap : best;
    best_axis = larger ? 6 + e : best_axis;
  }
}

// overlapAvx2's and overlapAvx512's kernel (obb3_lanes.hpp).
[[gnu::always_inline]] inline Verdict overlapVector(const double* a, const double* b, double phi) {
  Lanes p = poseAndFaces(a, b);
  const double face =
      largestLane(_mm256_max_pd(withoutPadding(p.face_a), withoutPadding(p.face_b)));
  if (face > 0.0) return Verdict::kSeparated;
  fastEdges(a, b, p);
  const double edge =
      largestLane(withoutPadding(_mm256_max_pd(_mm256_max_pd(p.gap[0], p.gap[1]), p.gap[2])));
  const double bound = edgeBound(a, b, phi).bound;
  if (edge > bound) return Verdict::kSeparated;
  if (edge < -bound) return Verdict::kOverlapping;
  return Verdict::kUndecided;
}

// largestGapAvx2's and largestGapAvx512's kernel (obb3_lanes.hpp).
[[gnu::always_inline]] inline bool largestGapVector(const double* a, const double* b, double phi,
                                                    LargestGap& out) {
  const EdgeBound filter = edgeBound(a, b, phi);
  // Outside the root-free comparison's range, no edge clears an infinite bound.
  const bool in_range = filter.scale >= kRootFreeMinScale && filter.scale <= kRootFreeMaxScale;
  const double bound = in_range ? filter.bound : __builtin_inf();
  const double min_length2 = filter.min_length2;
  Lanes p = poseAndFaces(a, b);
  _mm256_storeu_pd(out.t, p.t);
  _mm256_storeu_pd(out.tb, p.tb);
  for (int j = 0; j < 3; ++j) _mm256_storeu_pd(out.col[j], p.col[j]);
  // The first largest face gap: the comparisons are exact, so any order finds it (obb3.cpp runs
  // them in turn), and a face gap is never -0 (|t| - ha is +0 or non-zero, and so is the radius'
  // difference from it), so the largest value has the bits of the first face holding it.
  const double face =
      largestLane(_mm256_max_pd(withoutPadding(p.face_a), withoutPadding(p.face_b)));
  const __m256d faces = splat(face);
  const int holding = (_mm256_movemask_pd(_mm256_cmp_pd(p.face_a, faces, _CMP_EQ_OQ)) & 0b0111) |
                      (_mm256_movemask_pd(_mm256_cmp_pd(p.face_b, faces, _CMP_EQ_OQ)) & 0b0111)
                          << 3;
  fastEdges(a, b, p);
  const __m256d vbound = splat(bound), vmin_length2 = splat(min_length2);
  __m256d sure = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  for (int j = 0; j < 3; ++j) {
    sure = _mm256_and_pd(sure, _mm256_cmp_pd(abs4(p.gap[j]), vbound, _CMP_GT_OQ));
    sure = _mm256_and_pd(sure, _mm256_cmp_pd(p.length2[j], vmin_length2, _CMP_GT_OQ));
  }
  if ((_mm256_movemask_pd(sure) & 0b0111) != 0b0111) return false;
  double best = face;
  int best_axis = __builtin_ctz(static_cast<unsigned>(holding));
  if (!largestRootFree(p, best, best_axis)) largestNormalised(p, best, best_axis);
  out.gap = best;
  out.axis = best_axis;
  return true;
}

}  // namespace
}  // namespace cardemo::obb3_detail
