#pragma once
/// Internal to the grid scans: the walk over a window's occupied rows, shared by both versions.
//
// Internal linkage only: included by grid_scan_portable.cpp and grid_scan_avx2.cpp, each of which
// gets its own copy (compiled with its own instruction set).

#include <cstdint>

#include "collision/grid_scan.hpp"

namespace cardemo::grid_detail {
namespace {

// The first occupied row at or after y, or a row past y_last when there is none up to y_last.
// Empty rows (aisles, the gaps between parking rows) cost a bit scan, not two offset loads.
[[gnu::always_inline]] inline std::int64_t nextOccupiedRow(const std::uint64_t* row_bits,
                                                           std::int64_t y, std::int64_t y_last) {
  std::uint64_t word = row_bits[y >> 6] >> (y & 63);
  while (word == 0) {
    y = (y | 63) + 1;
    if (y > y_last) return y;
    word = row_bits[y >> 6];
  }
  return y + __builtin_ctzll(word);
}

// Scans the occupied rows of the window from row y on, calling step(k, end) for each group of
// boxes [k, k + step width) of each row while count + (the row's boxes) + padding fits in the
// buffer. Returns the row that did not fit, or a row past w.y1 when all did.
template <std::uint32_t kWidth, class Step>
[[gnu::always_inline]] inline std::int64_t scanFittingRows(const LevelArrays& level,
                                                           const ScanWindow& w, std::int64_t y,
                                                           std::size_t room, std::size_t& count,
                                                           const Step& step) {
  const std::uint32_t* const cell_start = level.cell_start;
  const std::uint64_t* const row_bits = level.row_bits;
  const std::int64_t nx = level.nx, x0 = w.x0, x1 = w.x1, y_last = w.y1;
  for (;; ++y) {
    y = nextOccupiedRow(row_bits, y, y_last);
    if (y > y_last) return y;
    const std::int64_t first_cell = y * nx;
    const std::uint32_t begin = cell_start[first_cell + x0];
    const std::uint32_t end = cell_start[first_cell + x1 + 1];
    if (end - begin + kScanStep > room - count) return y;
    for (std::uint32_t k = begin; k < end; k += kWidth) count = step(k, end, count);
  }
}

}  // namespace
}  // namespace cardemo::grid_detail
