// The grid scan two boxes at a time with SSE2 (part of the x86-64 baseline, so no CPU check),
// one at a time elsewhere.

#include "collision/grid_rows.hpp"
#include "collision/grid_scan.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cardemo::grid_detail {
namespace {

// Tests boxes k and k + 1 (lanes at or past `end` are ignored) and appends the ids of those that
// touch or overlap the query at buffer[count]; returns the new count. Writes two slots.
[[gnu::always_inline]] inline std::size_t step2(const LevelArrays& a, const ScanWindow& w,
                                                std::uint32_t k, std::uint32_t end,
                                                std::uint32_t* buffer, std::size_t count) {
  // Closed intervals: touching counts. Ordered comparisons, so a NaN box is never found.
#if defined(__SSE2__)
  __m128d in = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(a.min_x + k), _mm_set1_pd(w.max_x)),
                          _mm_cmple_pd(_mm_set1_pd(w.min_x), _mm_loadu_pd(a.max_x + k)));
  in = _mm_and_pd(in, _mm_cmple_pd(_mm_loadu_pd(a.min_y + k), _mm_set1_pd(w.max_y)));
  in = _mm_and_pd(in, _mm_cmple_pd(_mm_set1_pd(w.min_y), _mm_loadu_pd(a.max_y + k)));
  const unsigned bits = static_cast<unsigned>(_mm_movemask_pd(in)) & (end - k >= 2 ? 3u : 1u);
#else
  unsigned bits = 0;
  for (unsigned j = 0; j < 2; ++j) {
    const std::uint32_t i = k + j;
    bits |= static_cast<unsigned>((a.min_x[i] <= w.max_x) & (w.min_x <= a.max_x[i]) &
                                  (a.min_y[i] <= w.max_y) & (w.min_y <= a.max_y[i]))
            << j;
  }
  bits &= end - k >= 2 ? 3u : 1u;
#endif
  // Branchless: both ids are written, the count advances past the hits only (an overlap test is
  // a coin flip that a branch would mispredict).
  buffer[count] = a.ids[k];
  count += bits & 1u;
  buffer[count] = a.ids[k + 1];
  return count + (bits >> 1);
}

}  // namespace

void scanLevelPortable(const LevelArrays& level, const ScanWindow& w, IdSink& sink) {
  std::uint32_t* const buffer = sink.buffer;
  std::size_t count = sink.count;
  const auto step = [&](std::uint32_t k, std::uint32_t end, std::size_t n) {
    return step2(level, w, k, end, buffer, n);
  };
  for (std::int64_t y = w.y0;; ++y) {
    y = scanFittingRows<2>(level, w, y, sink.capacity, count, step);
    if (y > w.y1) break;
    // Row y's boxes do not fit in what is left of the buffer: empty it before each step.
    const std::int64_t first_cell = y * level.nx;
    const std::uint32_t end = level.cell_start[first_cell + w.x1 + 1];
    for (std::uint32_t k = level.cell_start[first_cell + w.x0]; k < end; k += 2) {
      if (sink.capacity - count < kScanStep) {
        sink.count = count;
        sink.flush(sink);
        count = sink.count;
      }
      count = step(k, end, count);
    }
  }
  sink.count = count;
}

}  // namespace cardemo::grid_detail
