#pragma once
/// Internal to sat_quads_avx2.cpp and sat_quads_avx512.cpp: the SAT of two quadrilaterals with
/// 256-bit vectors, compiled once per instruction set.
//
// Lanes (A's axis q, B's axis q, A's axis q+1, B's axis q+1), so two rounds cover all eight edge
// normals where the SSE2 path takes four. Every lane does the SSE2 path's operations in its order,
// so the gaps and keys are the same bit for bit. The AVX2 build has sixteen vector registers; the
// AVX-512VL build of the same source has thirty-two, so it spills less, and its operations are the
// same IEEE ones, so its bits are too. -ffp-contract=off keeps every product rounded on its own.
//
// Includes nothing but the intrinsics, sat_quads.hpp and lanes_avx2.hpp, for the reason given in
// lab/kernels/batch_avx2.cpp; everything here has internal linkage, so the two builds cannot be
// mixed up by the linker.

#include <immintrin.h>

#include "lab/geometry/sat_quads.hpp"
#include "lab/kernels/lanes_avx2.hpp"

namespace cardemo::sat_detail {
namespace {

using batch_detail::largestLane;

// Lanes 0, 2 (A's axes) from a, lanes 1, 3 (B's) from b.
[[gnu::always_inline]] inline __m256d aLanesFrom(__m256d a, __m256d b) {
  return _mm256_blend_pd(a, b, 0b1010);
}

[[gnu::always_inline]] inline __m256d project(__m256d nx, __m256d ny, __m256d x, __m256d y) {
  return _mm256_add_pd(_mm256_mul_pd(nx, x), _mm256_mul_pd(ny, y));
}

// The largest lane, in every lane.
[[gnu::always_inline]] inline __m256d largestInEveryLane(__m256d v) {
  const __m256d halves = _mm256_max_pd(v, _mm256_permute2f128_pd(v, v, 1));
  return _mm256_max_pd(halves, _mm256_permute_pd(halves, 0b0101));
}

[[gnu::always_inline]] inline double smallestLane(__m256d v) {
  const __m128d half = _mm_min_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_min_pd(half, _mm_unpackhi_pd(half, half)));
}

// widestAxisOfQuadsAvx2's and widestAxisOfQuadsAvx512's kernel (sat_quads.hpp).
[[gnu::always_inline]] inline bool widestAxisOfQuadsVector(const double* a, const double* b,
                                                           WidestAxis& out) {
  // World coordinates by vertex pairs: x01 = (A x0, B x0, A x1, B x1), and so on.
  const __m256d a01 = _mm256_loadu_pd(a), a23 = _mm256_loadu_pd(a + 4);
  const __m256d b01 = _mm256_loadu_pd(b), b23 = _mm256_loadu_pd(b + 4);
  const __m256d x01 = _mm256_unpacklo_pd(a01, b01), y01 = _mm256_unpackhi_pd(a01, b01);
  const __m256d x23 = _mm256_unpacklo_pd(a23, b23), y23 = _mm256_unpackhi_pd(a23, b23);
  const __m256d x12 = _mm256_permute2f128_pd(x01, x23, 0x21);
  const __m256d y12 = _mm256_permute2f128_pd(y01, y23, 0x21);
  const __m256d x30 = _mm256_permute2f128_pd(x23, x01, 0x21);
  const __m256d y30 = _mm256_permute2f128_pd(y23, y01, 0x21);
  // Edge normals from world coordinates, as the SSE2 path: (next.y - v.y, v.x - next.x).
  const __m256d nx[2] = {_mm256_sub_pd(y12, y01), _mm256_sub_pd(y30, y23)};
  const __m256d ny[2] = {_mm256_sub_pd(x01, x12), _mm256_sub_pd(x23, x30)};
  // Coordinates relative to A's first vertex.
  const __m256d ref_x = _mm256_set1_pd(a[0]), ref_y = _mm256_set1_pd(a[1]);
  const __m256d lx01 = _mm256_sub_pd(x01, ref_x), ly01 = _mm256_sub_pd(y01, ref_y);
  const __m256d lx23 = _mm256_sub_pd(x23, ref_x), ly23 = _mm256_sub_pd(y23, ref_y);
  const __m256d lx12 = _mm256_sub_pd(x12, ref_x), ly12 = _mm256_sub_pd(y12, ref_y);
  const __m256d lx30 = _mm256_sub_pd(x30, ref_x), ly30 = _mm256_sub_pd(y30, ref_y);
  const __m256d sign = _mm256_set1_pd(-0.0);
  const __m256d largest =
      _mm256_max_pd(_mm256_max_pd(_mm256_andnot_pd(sign, lx01), _mm256_andnot_pd(sign, ly01)),
                    _mm256_max_pd(_mm256_andnot_pd(sign, lx23), _mm256_andnot_pd(sign, ly23)));
  // Round r covers axes q = 2r, 2r+1: the axis's own vertex q (its high end), q+2 and q+3.
  const __m256d own_x[2][3] = {{lx01, lx23, lx30}, {lx23, lx01, lx12}};
  const __m256d own_y[2][3] = {{ly01, ly23, ly30}, {ly23, ly01, ly12}};
  // The other shape's vertex k in every lane: B's for A's axes, A's for B's.
  __m256d other_x[4], other_y[4];
  // Lane i takes element (imm >> 2i) & 3: (1, 0, 1, 0) and (3, 2, 3, 2).
  constexpr int kFirst = 0b00010001, kSecond = 0b10111011;
  other_x[0] = _mm256_permute4x64_pd(lx01, kFirst);
  other_y[0] = _mm256_permute4x64_pd(ly01, kFirst);
  other_x[1] = _mm256_permute4x64_pd(lx01, kSecond);
  other_y[1] = _mm256_permute4x64_pd(ly01, kSecond);
  other_x[2] = _mm256_permute4x64_pd(lx23, kFirst);
  other_y[2] = _mm256_permute4x64_pd(ly23, kFirst);
  other_x[3] = _mm256_permute4x64_pd(lx23, kSecond);
  other_y[3] = _mm256_permute4x64_pd(ly23, kSecond);

  // Per slot, what its normalisation needs: the gap, the axis pointing towards B, and its length
  // (a root off the critical path: only the winner's is used, but every lane's is ready by then).
  alignas(32) double gap_of[8], toward_x[8], toward_y[8], length_of[8];
  __m256d keys[2];
  __m256d smallest_length2 = _mm256_set1_pd(__builtin_inf());
  for (std::size_t r = 0; r < 2; ++r) {
    const __m256d x = nx[r], y = ny[r];
    const __m256d hi = project(x, y, own_x[r][0], own_y[r][0]);
    const __m256d lo = _mm256_min_pd(project(x, y, own_x[r][1], own_y[r][1]),
                                     project(x, y, own_x[r][2], own_y[r][2]));
    __m256d other_lo = project(x, y, other_x[0], other_y[0]);
    __m256d other_hi = other_lo;
    for (int k = 1; k < 4; ++k) {
      const __m256d d = project(x, y, other_x[k], other_y[k]);
      other_lo = _mm256_min_pd(other_lo, d);
      other_hi = _mm256_max_pd(other_hi, d);
    }
    // Towards B: A's forward gap is B's low end past A's high end; B's is the other way round.
    const __m256d u = _mm256_sub_pd(other_lo, hi), v = _mm256_sub_pd(lo, other_hi);
    const __m256d f = aLanesFrom(u, v), g = aLanesFrom(v, u);
    const __m256d gap = _mm256_max_pd(f, g);  // f > g ? f : g, as the SSE2 path
    const __m256d length2 = _mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y));
    keys[r] = _mm256_div_pd(_mm256_mul_pd(gap, _mm256_andnot_pd(sign, gap)), length2);
    // The normal is the axis when f >= g, else its negation; negating before the division gives
    // the same bits as after it.
    const __m256d flip = _mm256_andnot_pd(_mm256_cmp_pd(f, g, _CMP_GE_OQ), sign);
    _mm256_store_pd(gap_of + 4 * r, gap);
    _mm256_store_pd(toward_x + 4 * r, _mm256_xor_pd(x, flip));
    _mm256_store_pd(toward_y + 4 * r, _mm256_xor_pd(y, flip));
    _mm256_store_pd(length_of + 4 * r, _mm256_sqrt_pd(length2));
    smallest_length2 = _mm256_min_pd(smallest_length2, length2);
  }
  if (!(largestLane(largest) < kLargestFastCoordinate &&
        smallestLane(smallest_length2) > kSmallestFastLength2)) {
    return false;
  }
  // The first slot (A's axes 0-3, then B's) with the largest key, without a branch (a loop over
  // the slots mispredicts on most pairs of a large set). Bit 4 r + lane of `ties` is lane `lane`
  // of round r, so slot (shape s, axis q) is bit 4 (q / 2) + 2 (q % 2) + s: A's slots are the even
  // bits in axis order, B's the odd ones. Slot 7 when no key equals the largest, as a loop would.
  const __m256d top = largestInEveryLane(_mm256_max_pd(keys[0], keys[1]));
  const unsigned ties =
      static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(keys[0], top, _CMP_EQ_OQ))) |
      static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(keys[1], top, _CMP_EQ_OQ))) << 4;
  const unsigned a_ties = ties & 0x55u, b_ties = (ties & 0xAAu) | 0x80u;
  const int w = __builtin_ctz(a_ties != 0 ? a_ties : b_ties);
  // One division for the three quotients (IEEE division lane by lane: the scalar path's bits).
  const __m256d numerators = _mm256_setr_pd(gap_of[w], toward_x[w], toward_y[w], 0.0);
  alignas(32) double q[4];
  _mm256_store_pd(q, _mm256_div_pd(numerators, _mm256_broadcast_sd(length_of + w)));
  out = {q[0], q[1], q[2]};
  return true;
}

}  // namespace
}  // namespace cardemo::sat_detail
