#pragma once
/// Internal to the batch kernels: the float pre-filter of the 3D boolean SAT, written once over a
/// float lane type (eight floats with AVX2, sixteen with AVX-512) as the 2D one is
/// (batch2_filter.hpp, whose lane type interface it uses). It decides, in float, every pair whose
/// largest separating-axis gap clears a rigorous error bound, and hands the rest to the double
/// kernel, so every verdict equals that of the accurate kernel, bit for bit the portable path's.
//
// Included by filter_avx2.cpp and batch_avx512.cpp only; everything here has internal linkage.
//
// The gaps are those of the double kernels' A-frame filter (batch_kernels.hpp, fastEdge): with
// t = A^T d and R = A^T B, A's face i, B's face j and the edge axis a_i x b_j written in A's frame.
//
// Why the verdict is exact (lab/README.md, "The float pre-filters"). Write u = 2^-24, D =
// |d|_1 for the exact centre difference, H for the sum of the six half extents, S = D + H, and
// P = 1.0001 u (|xA|_1 + |xB|_1) for the rounding of the centres taken relative to the batch's
// reference point. Under the standard model fl(x op y) = (x op y)(1 + e), |e| <= u, an fma rounding
// once (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., 2.2 and ch. 3), with
// rotation entries and half extents rounded to float (relative error u each) and frames orthonormal
// to within phi <= 2^-30 (setFilter in obb3_batch.cpp turns the filter off beyond):
//   |d^ - d|_1 <= u D + 1.01 P;  |t^_i - t_i| <= 4.1 u D + 1.02 P;  |R^_ij - R_ij| <= 4.1 u
// (|t|_2 <= D, sum_k |a_ik| |b_jk| <= 1 + 2 phi). The gaps then follow: A's faces within
// 9.2 u S + 1.02 P, B's faces (s_j = sum_i t_i R_ij, which is d . b_j up to 3 phi D since
// A A^T = I up to 3 phi; sum_i |R_ij| <= 1.74) within 20.7 u S + 1.78 P, the edges within
// 24.6 u S + 2.04 P. The exact A-frame gap is within
// (26 * 2^-53 + 2 phi) S < u S / 8 of the accurate kernel's (architecture.md, "The 3D filter"),
// and the accurate face gaps within 10 * 2^-53 S of theirs. So every float gap is within
// E = 24.8 u S + 2.04 P of the accurate kernel's gap on the same axis (0 on an edge axis the
// accurate kernel skips: its cross product is exactly zero). When the largest float gap m exceeds
// E, some accurate gap is positive on an axis the kernel uses: separated; when m < -E, every
// accurate gap is negative: not separated. The margin used is
// 2^-17 (|d^|_1 + H) + 2^-21 (|xA^|_1 + |xB^|_1) + 2^-100, each share rounded up: about five
// times E (2^-17 = 128 u, 2^-21 = 8 u); its last term covers underflow (absolute errors below
// 2^-149 per operation). Inputs are limited to 2^60 m, so no float operation overflows.

#include <cstddef>
#include <cstdint>

#include "lab/kernels/batch_entry.hpp"
#include "lab/kernels/filter_run.hpp"

namespace cardemo::batch_detail {
namespace {

// The float margin's coefficient of |d^|_1 (and of the half extents, in each box's share).
inline constexpr float kFilter3Scale = 0x1p-17f;

// The query box's float fields, one copy per lane.
template <class F>
struct FilterQuery3 {
  F c[3];     // centre minus the batch's reference point
  F a[3][3];  // a[i][k]: component k of A's axis i
  F h[3];     // half extents
  F bound;    // A's share of the margin
};

template <class F>
FilterQuery3<F> splatQuery3(const Box3FilterOne& one) {
  FilterQuery3<F> q;
  for (int k = 0; k < 3; ++k) {
    q.c[k] = F::splat(one.c[k]);
    q.h[k] = F::splat(one.h[k]);
    for (int i = 0; i < 3; ++i) q.a[i][k] = F::splat(one.r[3 * i + k]);
  }
  q.bound = F::splat(one.bound);
  return q;
}

// The fifteen gaps of the A-frame SAT in float, their largest, and the verdict against the margin.
template <class F>
[[gnu::always_inline]] inline FilterVerdict filter3(const FilterQuery3<F>& a,
                                                    const Box3FilterArrays& b, std::size_t i) {
  const F d[3] = {F::load(b.c[0] + i) - a.c[0], F::load(b.c[1] + i) - a.c[1],
                  F::load(b.c[2] + i) - a.c[2]};
  F t[3], r[3][3], ar[3][3];
  for (int p = 0; p < 3; ++p) {
    t[p] = fmadd(a.a[p][0], d[0], fmadd(a.a[p][1], d[1], a.a[p][2] * d[2]));
  }
  for (std::size_t q = 0; q < 3; ++q) {
    const F b0 = F::load(b.r[3 * q] + i), b1 = F::load(b.r[3 * q + 1] + i);
    const F b2 = F::load(b.r[3 * q + 2] + i);
    for (int p = 0; p < 3; ++p) {
      r[p][q] = fmadd(a.a[p][0], b0, fmadd(a.a[p][1], b1, a.a[p][2] * b2));
      ar[p][q] = abs(r[p][q]);
    }
  }
  const F hb[3] = {F::load(b.h[0] + i), F::load(b.h[1] + i), F::load(b.h[2] + i)};
  const auto face_a = [&](int p) {
    return fnmadd(hb[2], ar[p][2],
                  fnmadd(hb[1], ar[p][1], fnmadd(hb[0], ar[p][0], abs(t[p]) - a.h[p])));
  };
  F m = max(face_a(0), max(face_a(1), face_a(2)));
  for (int q = 0; q < 3; ++q) {  // B's faces
    const F s = fmadd(t[0], r[0][q], fmadd(t[1], r[1][q], t[2] * r[2][q]));
    m = max(m, fnmadd(a.h[2], ar[2][q],
                      fnmadd(a.h[1], ar[1][q], fnmadd(a.h[0], ar[0][q], abs(s) - hb[q]))));
  }
  for (int p = 0; p < 3; ++p) {  // edges a_p x b_q
    const int p1 = (p + 1) % 3, p2 = (p + 2) % 3;
    for (int q = 0; q < 3; ++q) {
      const int q1 = (q + 1) % 3, q2 = (q + 2) % 3;
      const F along = fmsub(t[p2], r[p1][q], t[p1] * r[p2][q]);
      const F g = fnmadd(a.h[p1], ar[p2][q],
                         fnmadd(a.h[p2], ar[p1][q],
                                fnmadd(hb[q1], ar[p][q2], fnmadd(hb[q2], ar[p][q1], abs(along)))));
      m = max(m, g);
    }
  }
  const F reach = abs(d[0]) + abs(d[1]) + abs(d[2]);
  const F margin = fmadd(F::splat(kFilter3Scale), reach, a.bound + F::load(b.bound + i));
  return {gtBits(m, margin), gtBits(abs(m), margin)};
}

// Runs the filter over [first, last) (runFilteredByBox, filter_run.hpp): `exact_boxes(indices,
// count)` decides the boxes it leaves open.
template <class F, class ExactBoxes>
std::size_t runFilteredOverlap3(const Box3FilterOne& fa, const Box3FilterArrays& fb,
                                std::size_t first, std::size_t last, std::uint8_t* hit,
                                const ExactBoxes& exact_boxes) {
  const FilterQuery3<F> q = splatQuery3<F>(fa);
  const Box3FilterArrays b = fb;
  return runFilteredByBox<F::kWidth>(
      first, last, hit, [&q, b](std::size_t i) { return filter3<F>(q, b, i); }, exact_boxes,
      [](std::size_t) {});
}

}  // namespace
}  // namespace cardemo::batch_detail
