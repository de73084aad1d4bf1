#pragma once
/// Internal to UniformGrid: the scan over one level's cells for a query, in two versions chosen at
/// run time (geometry/batch_path): two boxes per SSE2 instruction (the x86-64 baseline, scalar
/// elsewhere) and four per AVX2 instruction. Both find the same boxes in the same order.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as geometry/batch_entry.hpp).

#include <cstddef>
#include <cstdint>

namespace cardemo::grid_detail {

/// Where a scan writes the ids it finds: buffer[0, count), emptied by `flush` (which moves them
/// out and sets count to 0) whenever fewer than kScanStep slots are left.
struct IdSink {
  std::uint32_t* buffer;        ///< Ids found, in scan order.
  std::size_t capacity;         ///< Slots in buffer (at least kScanStep).
  std::size_t count;            ///< Slots in use.
  void (*flush)(IdSink& sink);  ///< Empties the buffer.
  void* owner;                  ///< For flush: where the ids go.
};

/// Largest number of slots one step of a scan writes (every slot, not only the hits).
inline constexpr std::size_t kScanStep = 4;

/// Entries past the last box of a level's arrays, so a step may read a whole group of boxes.
inline constexpr std::size_t kScanPadding = kScanStep - 1;

/// One level of the grid, struct of arrays: box k is [min_x[k], max_x[k]] x [min_y[k], max_y[k]]
/// in world metres, with item id ids[k]; boxes are grouped by cell, cells in row-major order, cell
/// c holding [cell_start[c], cell_start[c + 1]). Bit y % 64 of row_bits[y / 64] is set when row y
/// holds a box.
struct LevelArrays {
  const double *min_x, *min_y, *max_x, *max_y;  ///< Box bounds, metres.
  const std::uint32_t* ids;                     ///< Item ids.
  const std::uint32_t* cell_start;              ///< nx * ny + 1 offsets.
  const std::uint64_t* row_bits;                ///< Occupied rows.
  std::int64_t nx;                              ///< Cells per row.
};

/// The cells [x0, x1] x [y0, y1] a query reaches and the query box itself (closed, metres).
struct ScanWindow {
  std::int64_t x0, x1, y0, y1;  ///< Cell ranges, inclusive.
  double min_x, min_y;          ///< Query's lower-left corner.
  double max_x, max_y;          ///< Query's upper-right corner.
};

/// Writes to `sink` the id of every box in the window's cells that touches or overlaps the query,
/// row by row, cells and boxes in storage order.
void scanLevelPortable(const LevelArrays& level, const ScanWindow& window, IdSink& sink);
/// The same with AVX2; call only when geometry/batch_path says the CPU has it.
void scanLevelAvx2(const LevelArrays& level, const ScanWindow& window, IdSink& sink);

}  // namespace cardemo::grid_detail
