#pragma once
/// Internal to the grid scans: the parts both versions share (the window of cells a query
/// reaches, the walk over its occupied rows, the whole scan given a step).
//
// Internal linkage only: included by grid_scan_portable.cpp and grid_scan_avx2.cpp, each of which
// gets its own copy (compiled with its own instruction set).

#include <cstdint>

#include "collision/grid_scan.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cardemo::grid_detail {
namespace {

// The cells [x0, x1] x [y0, y1] of a level that hold the lower-left corner of every box that may
// touch the query.
struct Window {
  std::int64_t x0, x1, y0, y1;
};

// Cell index of coordinate x: the same IEEE operations as cellOf in broad_phase.cpp (which builds
// the level), so a box's corner and the query's window agree on cells. Clamped while still a
// double (a huge or NaN coordinate cannot overflow the conversion); the map is monotone.
[[gnu::always_inline]] inline std::int64_t cellIndex(double x, double origin, double inv_cell,
                                                     double last) {
  double t = (x - origin) * inv_cell;
  t = 0.0 < t ? t : 0.0;  // std::max(0.0, t): NaN goes to 0
  t = last < t ? last : t;
  return static_cast<std::int64_t>(t);
}

// An overlapping box has its corner at or above query.min - reach (broad_phase.cpp, buildLevel),
// and the cell map is monotone, so these cells hold every box that may touch the query.
[[gnu::always_inline]] inline Window windowOf(const LevelArrays& l, const double* q_min,
                                              const double* q_max) {
#if defined(__SSE2__)
  // Both axes at once; max(t, 0) returns its second operand (0) for NaN, as cellIndex does.
  const __m128d origin = _mm_loadu_pd(l.bounds_min), inv = _mm_loadu_pd(l.inv_cell);
  const __m128d last = _mm_loadu_pd(l.last_cell), zero = _mm_setzero_pd();
  const __m128d low = _mm_sub_pd(_mm_loadu_pd(q_min), _mm_loadu_pd(l.reach));
  const __m128d lo = _mm_min_pd(_mm_max_pd(_mm_mul_pd(_mm_sub_pd(low, origin), inv), zero), last);
  const __m128d hi =
      _mm_min_pd(_mm_max_pd(_mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(q_max), origin), inv), zero), last);
  // Cell indices are below 2^30, so 32-bit conversions are exact.
  const __m128i lo_cells = _mm_cvttpd_epi32(lo), hi_cells = _mm_cvttpd_epi32(hi);
  return {_mm_cvtsi128_si32(lo_cells), _mm_cvtsi128_si32(hi_cells),
          _mm_cvtsi128_si32(_mm_shuffle_epi32(lo_cells, 1)),
          _mm_cvtsi128_si32(_mm_shuffle_epi32(hi_cells, 1))};
#else
  return {cellIndex(q_min[0] - l.reach[0], l.bounds_min[0], l.inv_cell[0], l.last_cell[0]),
          cellIndex(q_max[0], l.bounds_min[0], l.inv_cell[0], l.last_cell[0]),
          cellIndex(q_min[1] - l.reach[1], l.bounds_min[1], l.inv_cell[1], l.last_cell[1]),
          cellIndex(q_max[1], l.bounds_min[1], l.inv_cell[1], l.last_cell[1])};
#endif
}

// The same for a QueryBox.
[[gnu::always_inline]] inline Window windowOf(const LevelArrays& l, const QueryBox& q) {
  return windowOf(l, q.min, q.max);
}

// True when the query touches the level's bounds (false for a NaN query).
[[gnu::always_inline]] inline bool touchesBounds(const LevelArrays& l, const QueryBox& q) {
  return (l.bounds_min[0] <= q.max[0]) & (q.min[0] <= l.bounds_max[0]) &
         (l.bounds_min[1] <= q.max[1]) & (q.min[1] <= l.bounds_max[1]);
}

// The occupied rows among base .. min(y_last, base + 63): bit r set when row base + r holds a box.
// One funnel shift of two words (row_bits has a word past the last row's, so the second is always
// there): empty rows (aisles, the gaps between parking rows) cost nothing, and a query's few rows
// one bit scan each.
[[gnu::always_inline]] inline std::uint64_t occupiedRows(const std::uint64_t* row_bits,
                                                         std::int64_t base, std::int64_t y_last) {
  const std::uint64_t* const w = row_bits + (base >> 6);
  const unsigned shift = static_cast<unsigned>(base & 63);
  // The second shift is split in two so that a zero `shift` is defined.
  std::uint64_t rows = (w[0] >> shift) | ((w[1] << 1) << (63 - shift));
  const std::int64_t last = y_last - base;
  if (last < 63) rows &= (std::uint64_t{2} << last) - 1;
  return rows;
}

// A level's box arrays, copied into a local before a scan: the scans store ids through
// may-alias vector stores, which would otherwise reload every pointer after each store.
struct Boxes {
  const double *min_x, *min_y, *max_x, *max_y;
  const std::uint32_t* ids;
};

// The whole scan, given step(boxes, k, end, buffer, count): tests the boxes [k, k + kWidth) of a
// row whose boxes end at `end`, writes kWidth slots at buffer[count] (the found ids first) and
// returns the new count.
template <std::uint32_t kWidth, class Step>
[[gnu::always_inline]] inline void scanLevels(const LevelArrays* levels, std::size_t level_count,
                                              const QueryBox& q, IdSink& sink, const Step& step) {
  std::uint32_t* const buffer = sink.buffer;
  const std::size_t capacity = sink.capacity;
  std::size_t count = sink.count;
  for (std::size_t i = 0; i < level_count; ++i) {
    const LevelArrays& l = levels[i];
    if (!touchesBounds(l, q)) continue;
    const Window w = windowOf(l, q);
    const Boxes boxes{l.min_x, l.min_y, l.max_x, l.max_y, l.ids};
    const std::uint32_t* const cell_start = l.cell_start;
    const std::uint64_t* const row_bits = l.row_bits;
    const std::int64_t row_stride = l.row_stride;
    for (std::int64_t base = w.y0; base <= w.y1; base += 64) {
      for (std::uint64_t rows = occupiedRows(row_bits, base, w.y1); rows != 0; rows &= rows - 1) {
        const std::int64_t first_cell = (base + __builtin_ctzll(rows)) * row_stride;
        std::uint32_t k = cell_start[first_cell + w.x0];
        const std::uint32_t end = cell_start[first_cell + w.x1 + 1];
        if (end - k + kScanStep <= capacity - count) [[likely]] {
          // One step whatever the row holds (an empty row's lanes are all masked): most rows
          // hold a handful of boxes, and a fixed step costs less than the branches that would
          // skip it.
          count = step(boxes, k, end, buffer, count);
          for (k += kWidth; k < end; k += kWidth) count = step(boxes, k, end, buffer, count);
          continue;
        }
        // The row's boxes may not fit in what is left of the buffer: empty it when needed.
        for (; k < end; k += kWidth) {
          if (capacity - count < kScanStep) {
            sink.count = count;
            sink.flush(sink);
            count = sink.count;
          }
          count = step(boxes, k, end, buffer, count);
        }
      }
    }
  }
  sink.count = count;
}

}  // namespace
}  // namespace cardemo::grid_detail
