#pragma once
/// Internal to the batch kernels: the float pre-filter of the 2D boolean SAT, written once over a
/// float lane type (eight floats with AVX2, sixteen with AVX-512F). It decides, in float, every
/// pair whose largest separating-axis gap clears a rigorous error bound, and hands the rest (pairs
/// within about 1e-5 m of touching) to the double kernel, so every verdict equals overlapObb2's.
///
/// A float lane type F provides: F::kWidth, F::load(const float*), F::splat(float), + - *,
/// fmadd(a, b, c) = a*b + c, fmsub(a, b, c) = a*b - c, fnmadd(a, b, c) = c - a*b (each rounded
/// once), abs, max, and gtBits(a, b): bit k set when lane k of a > lane k of b.
//
// Included by filter_avx2.cpp and batch_avx512.cpp only; everything here has internal linkage.
//
// Why the verdict is exact (lab/README.md, "The float pre-filters", sums it up).
// Write u = 2^-24, R = |cB - cA|, H = hAx + hAy + hBx + hBy, and g_k for the gap on axis k computed
// with exact arithmetic from the stored doubles (the quantity overlapObb2 rounds). Under the
// standard model fl(x op y) = (x op y)(1 + d), |d| <= u (Higham, "Accuracy and Stability of
// Numerical Algorithms", 2nd ed., 2.2 and ch. 3), the float gaps below are within
// 16.4 u R + 8 u H + 1.42 P of g_k, where P = 1.0001 u (|xA| + |yA| + |xB| + |yB|) covers the
// rounding of the centres taken relative to the batch's reference point; the double kernel's own
// gaps are within 1e-8 u (R + H) of g_k. The largest float gap m also bounds the distance:
// R <= sqrt(2) (m + H + 1.42 P)(1 + 24 u). Together: when |m| > 31.1 u H + 1.42 P, the float and
// the double gaps agree in sign on the deciding axes, so m > 0 means some double gap is > 0
// (separated) and m < 0 means every double gap is < 0 (overlapping). The margin used,
// 2^-18 H + 2^-22 (|xA| + |yA| + max |xB| + |yB|) + 2^-100, rounded up, is about twice that; its
// last term covers underflow (absolute errors below 2^-149 per operation). Inputs are limited to
// 2^60 m (checked per batch and per call), so no float operation overflows.

#include <cstddef>
#include <cstdint>

#include "lab/kernels/batch_entry.hpp"
#include "lab/kernels/filter_run.hpp"

namespace cardemo::batch_detail {
namespace {

// The query box's float fields, one copy per lane.
template <class F>
struct FilterQuery2 {
  F x, y, ux, uy, hx, hy, bound;
};

template <class F>
FilterQuery2<F> splatQuery(const Box2FilterOne& a) {
  return {F::splat(a.x),  F::splat(a.y),  F::splat(a.ux),   F::splat(a.uy),
          F::splat(a.hx), F::splat(a.hy), F::splat(a.bound)};
}

// The four gaps of overlapObb2 in float, in A's frame after the centre difference. Explicit fused
// multiply-adds round fewer times than the bound allows for; they cannot change a verdict.
template <class F>
[[gnu::always_inline]] inline FilterVerdict filter2(const FilterQuery2<F>& a,
                                                    const Box2FilterArrays& b, std::size_t i) {
  const F dx = F::load(b.x + i) - a.x;
  const F dy = F::load(b.y + i) - a.y;
  const F bux = F::load(b.ux + i), buy = F::load(b.uy + i);
  const F hbx = F::load(b.hx + i), hby = F::load(b.hy + i);
  const F tx = fmadd(a.ux, dx, a.uy * dy);
  const F ty = fmsub(a.ux, dy, a.uy * dx);
  const F c = fmadd(a.ux, bux, a.uy * buy);
  const F s = fmsub(a.ux, buy, a.uy * bux);
  const F tbx = fmadd(c, tx, s * ty);
  const F tby = fmsub(c, ty, s * tx);
  const F ac = abs(c), as = abs(s);
  const F g0 = fnmadd(as, hby, fnmadd(ac, hbx, abs(tx) - a.hx));
  const F g1 = fnmadd(ac, hby, fnmadd(as, hbx, abs(ty) - a.hy));
  const F g2 = fnmadd(as, a.hy, fnmadd(ac, a.hx, abs(tbx) - hbx));
  const F g3 = fnmadd(ac, a.hy, fnmadd(as, a.hx, abs(tby) - hby));
  const F m = max(max(g0, g1), max(g2, g3));
  const F margin = F::load(b.bound + i) + a.bound;
  return {gtBits(m, margin), gtBits(abs(m), margin)};
}

// Runs the filter over [first, last) (runFiltered, filter_run.hpp).
template <class F, class Exact>
std::size_t runFilteredOverlap2(const Box2FilterOne& fa, const Box2FilterArrays& fb,
                                std::size_t first, std::size_t last, std::uint8_t* hit,
                                const Exact& exact) {
  // Local copies: the byte stores to `hit` may alias anything, so pointers read through a
  // reference would be reloaded after every store.
  const FilterQuery2<F> q = splatQuery<F>(fa);
  const Box2FilterArrays b = fb;
  return runFiltered<F::kWidth>(
      first, last, hit, [q, b](std::size_t i) { return filter2<F>(q, b, i); }, exact);
}

}  // namespace
}  // namespace cardemo::batch_detail
