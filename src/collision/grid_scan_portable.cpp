// The grid scan two boxes at a time with SSE2 (part of the x86-64 baseline, so no CPU check),
// one at a time elsewhere.

#include "collision/grid_rows.hpp"
#include "collision/grid_scan.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cardemo::grid_detail {
namespace {

// Lanes [0, n) of a two-box step, for the n boxes left in a row (2 or more: both).
unsigned liveLanes(std::uint32_t left) {
  return (1u << (left < 2 ? left : 2)) - 1u;
}

}  // namespace

void scanLevelsPortable(const LevelArrays* levels, std::size_t level_count, const QueryBox& q,
                        IdSink& sink) {
#if defined(__SSE2__)
  const __m128d qmin_x = _mm_set1_pd(q.min[0]), qmin_y = _mm_set1_pd(q.min[1]);
  const __m128d qmax_x = _mm_set1_pd(q.max[0]), qmax_y = _mm_set1_pd(q.max[1]);
#endif
  const auto step2 = [&](const Boxes& a, std::uint32_t k, std::uint32_t end, std::uint32_t* buffer,
                         std::size_t count) {
  // Closed intervals: touching counts. Ordered comparisons, so a NaN box is never found.
#if defined(__SSE2__)
    __m128d in = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(a.min_x + k), qmax_x),
                            _mm_cmple_pd(qmin_x, _mm_loadu_pd(a.max_x + k)));
    in = _mm_and_pd(in, _mm_cmple_pd(_mm_loadu_pd(a.min_y + k), qmax_y));
    in = _mm_and_pd(in, _mm_cmple_pd(qmin_y, _mm_loadu_pd(a.max_y + k)));
    const unsigned bits = static_cast<unsigned>(_mm_movemask_pd(in)) & liveLanes(end - k);
#else
    unsigned bits = 0;
    for (unsigned j = 0; j < 2; ++j) {
      const std::uint32_t i = k + j;
      bits |= static_cast<unsigned>((a.min_x[i] <= q.max[0]) & (q.min[0] <= a.max_x[i]) &
                                    (a.min_y[i] <= q.max[1]) & (q.min[1] <= a.max_y[i]))
              << j;
    }
    bits &= liveLanes(end - k);
#endif
    // Branchless: both ids are written, the count advances past the hits only (an overlap test
    // is a coin flip that a branch would mispredict).
    buffer[count] = a.ids[k];
    count += bits & 1u;
    buffer[count] = a.ids[k + 1];
    return count + (bits >> 1);
  };
  scanLevels<2>(levels, level_count, q, sink, step2);
}

}  // namespace cardemo::grid_detail
