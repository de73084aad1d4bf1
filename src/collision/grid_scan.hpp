#pragma once
/// Internal to UniformGrid: a query's scan over the levels' cells, in two versions chosen at run
/// time (geometry/batch_path): two boxes per SSE2 instruction (the x86-64 baseline, scalar
/// elsewhere) and four per AVX2 instruction. Both find the same boxes in the same order.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as lab/kernels/batch_entry.hpp).

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

/// Boxes that nothing finds (NaN) after the boxes of each occupied row of a level, so that a step
/// may read a whole group of boxes from anywhere in the row, even from its end (an empty window),
/// without masking the lanes past the row: those lanes hold the row's later boxes, which lie in
/// cells right of the query's window and fail its x test, or these.
inline constexpr std::size_t kRowPadding = kScanStep;

/// One level of the grid as plain data, struct of arrays: box k is [min_x[k], max_x[k]] x
/// [min_y[k], max_y[k]] in world metres, with item id ids[k]; boxes are grouped by the cell of
/// their lower-left corner, cells in row-major order, each occupied row's boxes followed by
/// kRowPadding NaN boxes. Cell x of row y holds [cell_start[y * row_stride + x], cell_start[y *
/// row_stride + x + 1]); entry y * row_stride + nx is where row y's boxes end. Bit y % 64 of
/// row_bits[y / 64] is set when row y holds a box; row_bits has one word (zero) past the last
/// row's.
struct LevelArrays {
  const double *min_x, *min_y, *max_x, *max_y;  ///< Box bounds, metres.
  const std::uint32_t* ids;                     ///< Item ids.
  const std::uint32_t* cell_start;              ///< ny * row_stride offsets.
  const std::uint64_t* row_bits;                ///< Occupied rows.
  double bounds_min[2], bounds_max[2];          ///< Union of the level's boxes (x, y), metres.
  double reach[2];                              ///< Rounded-up largest box extent (x, y), metres.
  double inv_cell[2];                           ///< 1 / cell width and height, 1/m.
  double last_cell[2];                          ///< nx - 1 and ny - 1 (at most 2^30 - 1 each).
  std::int64_t row_stride;                      ///< Cells per row + 1 (cell_start entries a row).
};

/// A query box, closed, world metres.
struct QueryBox {
  double min[2];  ///< Lower-left corner (x, y).
  double max[2];  ///< Upper-right corner (x, y).
};

/// Writes to `sink` the id of every box of `levels[0, level_count)` that touches or overlaps the
/// query: level by level, row by row, in storage order. The query must not be NaN.
void scanLevelsPortable(const LevelArrays* levels, std::size_t level_count, const QueryBox& query,
                        IdSink& sink);
/// The same with AVX2; call only when geometry/batch_path says the CPU has it.
void scanLevelsAvx2(const LevelArrays* levels, std::size_t level_count, const QueryBox& query,
                    IdSink& sink);

/// Most ids scanFewAvx2 hands back.
inline constexpr std::size_t kFewIds = 8;

/// The common case of a query, with AVX2: returns how many boxes touch the closed box [query_min,
/// query_max] (each pointing to x then y) and, when that is at most kFewIds, writes their ids to
/// few[0, kFewIds) in increasing order (the slots past the count hold 0xFFFFFFFF). A larger count
/// leaves `few` unspecified: run scanLevelsAvx2 instead. Writes nothing else to memory. Call only
/// when geometry/batch_path says the CPU has AVX2.
std::size_t scanFewAvx2(const LevelArrays* levels, std::size_t level_count, const double* query_min,
                        const double* query_max, std::uint32_t* few);

/// The type of scanFewAvx2, which UniformGrid keeps a pointer to (null when it is not built).
using ScanFew = std::size_t (*)(const LevelArrays* levels, std::size_t level_count,
                                const double* query_min, const double* query_max,
                                std::uint32_t* few);

}  // namespace cardemo::grid_detail
