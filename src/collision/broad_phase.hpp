#pragma once
/// Static broad phase over the parked cars and obstacles: a uniform grid built once.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collision/grid_scan.hpp"
#include "geometry/aabb.hpp"
#include "geometry/batch_path.hpp"

namespace cardemo {

/// The ids a UniformGrid query found, in increasing order, in storage that the next query reuses
/// (no allocation once it has grown to its peak). What the game's step uses: the grid writes the
/// common handful of ids straight into it, with none of std::vector's bookkeeping.
class QueryIds {
 public:
  /// Empty, with room for the grid's fixed block of few ids (so the common query never resizes).
  QueryIds() : storage_(grid_detail::kFewIds) {}
  /// Copies.
  QueryIds(const QueryIds& other) = default;
  /// Copies.
  QueryIds& operator=(const QueryIds& other) = default;
  /// Takes the ids; `other` is left empty (its storage is restored at its next query).
  QueryIds(QueryIds&& other) noexcept
      : storage_(std::move(other.storage_)), count_(std::exchange(other.count_, 0)) {}
  /// Takes the ids; `other` is left empty.
  QueryIds& operator=(QueryIds&& other) noexcept {
    storage_ = std::move(other.storage_);
    count_ = std::exchange(other.count_, 0);
    return *this;
  }
  /// Frees the storage.
  ~QueryIds() = default;

  /// The ids, in increasing order.
  [[nodiscard]] std::span<const std::uint32_t> ids() const { return {storage_.data(), count_}; }
  /// Number of ids.
  [[nodiscard]] std::size_t size() const { return count_; }
  /// True when the query found nothing.
  [[nodiscard]] bool empty() const { return count_ == 0; }
  /// First id (for range for).
  [[nodiscard]] const std::uint32_t* begin() const { return storage_.data(); }
  /// Past the last id.
  [[nodiscard]] const std::uint32_t* end() const { return storage_.data() + count_; }
  /// Id k, k < size().
  [[nodiscard]] std::uint32_t operator[](std::size_t k) const { return storage_[k]; }
  /// Makes room for `n` ids ahead of time, so that no query allocates until one finds more.
  void reserve(std::size_t n) { storage_.reserve(n); }

 private:
  friend class UniformGrid;
  // storage_[0, count_) are the ids. storage_ holds at least kFewIds entries (a moved-from one
  // regains them at its next query), so that the grid writes its fixed block of few ids with no
  // size change.
  std::vector<std::uint32_t> storage_;
  std::size_t count_ = 0;
};

/// Uniform grids in compressed-sparse-row form over static boxes, one grid per size class. Each
/// box is stored once, in the cell that holds its lower-left corner, and the cells of a row are
/// contiguous, so a query scans one contiguous run of boxes per occupied row of cells it reaches,
/// four boxes per AVX2 instruction (two per SSE2 instruction on CPUs without AVX2; chosen as the
/// batch kernels are, geometry/batch_path). Build is O(N); a query's cost depends on the boxes
/// near it, not on how many there are. Queries do not modify the grid, so concurrent queries are
/// safe.
class UniformGrid {
 public:
  /// Builds the grid over `boxes` (index i of the span is the item id). Cell sizes follow the
  /// typical box size; the grid covers the union of the boxes. An empty span is allowed.
  explicit UniformGrid(std::span<const Aabb2> boxes);
  /// Copies (the scans' views of the levels are rebuilt for the copy's own arrays).
  UniformGrid(const UniformGrid& other);
  /// Copies (as the copy constructor).
  UniformGrid& operator=(const UniformGrid& other);
  /// Moves (the arrays keep their addresses, so do the views); `other` is left empty.
  UniformGrid(UniformGrid&& other) noexcept;
  /// Moves; `other` is left empty.
  UniformGrid& operator=(UniformGrid&& other) noexcept;
  /// Frees the levels.
  ~UniformGrid() = default;

  /// Appends to `out` (after clearing it) the ids of every box that touches or overlaps `query`,
  /// each once, in increasing id order. Does not allocate once `out` has grown to its peak size.
  void query(const Aabb2& query, std::vector<std::uint32_t>& out) const;
  /// The same ids into `out`: the cheaper form (no std::vector size bookkeeping per query).
  void query(const Aabb2& query, QueryIds& out) const {
    // Inline, so that the common case costs its caller one call (the scan) and no copy of the box.
    // A moved-from `out` has lost its storage: the crowded path restores it.
    if (out.storage_.size() >= grid_detail::kFewIds && scansFew()) [[likely]] {
      const std::size_t count = scan_few_(views_.data(), level_count_, query.min.data(),
                                          query.max.data(), out.storage_.data());
      if (count <= grid_detail::kFewIds) [[likely]] {
        out.count_ = count;
        return;
      }
    }
    queryCrowded(query, out);
  }

  /// Number of items the grid was built over.
  [[nodiscard]] std::size_t size() const { return size_; }
  /// Heap bytes held by the structure (for bytes-per-car reports).
  [[nodiscard]] std::size_t memoryBytes() const;
  /// Number of size classes in use (1 for a lot of similar cars), not counting oversized items.
  [[nodiscard]] std::size_t levelCount() const { return levels_.size(); }
  /// Width (x) and height (y) of the cells of level `k` (k < levelCount()), metres.
  [[nodiscard]] Eigen::Vector2d cellSize(std::size_t k) const {
    return levels_[k].inv_cell.cwiseInverse();
  }

 private:
  // One grid over the items of one size class, struct of arrays laid out as grid_scan.hpp's
  // LevelArrays describes (row_stride = nx + 1): item k lies in the cell of its lower-left corner;
  // cells are in row-major order; each occupied row's items are followed by kRowPadding NaN boxes,
  // so a scan step may read a whole group of boxes from anywhere in a row.
  struct Level {
    Aabb2 bounds;                        // union of the level's boxes
    Eigen::Vector2d inv_cell{1.0, 1.0};  // 1 / cell width and height, 1/m
    Eigen::Vector2d reach;               // rounded-up largest box extent along x and y, metres
    std::int64_t nx = 0, ny = 0;
    std::vector<std::uint32_t> cell_start;
    std::vector<double> min_x, min_y, max_x, max_y;
    std::vector<std::uint32_t> ids;
    std::vector<std::uint64_t> row_bits;  // bit y % 64 of word y / 64: row y holds an item
  };

  std::size_t size_ = 0;
  Aabb2 bounds_;
  std::vector<Level> levels_;
  std::vector<grid_detail::LevelArrays> views_;  // the scans' plain view of each level
  std::size_t level_count_ = 0;                  // views_.size(), kept for the inline query
  // grid_detail::scanFewAvx2 when it is built and no item is oversized, else null.
  grid_detail::ScanFew scan_few_ = nullptr;
  std::vector<Aabb2> large_boxes_;  // items too big for any level: tested by every query
  std::vector<std::uint32_t> large_ids_;

  // The common case with AVX2: writes kFewIds slots at `few` (the ids found first, in increasing
  // order) and returns how many were found, or more than kFewIds when they did not fit (`few` is
  // then unspecified); none when the path does not apply (oversized items, or no AVX2).
  [[nodiscard]] std::size_t queryFew(const Aabb2& query, std::uint32_t* few) const;
  // True when the few-ids scan applies: it is built, no item is oversized and the batch path is
  // not the portable one.
  [[nodiscard]] bool scansFew() const {
    return scan_few_ != nullptr && batchPath() != BatchPath::kPortable;
  }
  // query(QueryIds) when the few-ids scan does not apply or finds more than it keeps. Out of
  // line, so the inline common path stays small.
  void queryCrowded(const Aabb2& query, QueryIds& out) const;
  // The query when scanFewAvx2 is not used or finds more than it keeps: the scan stores ids to a
  // buffer, which is then sorted.
  void queryBuffered(const Aabb2& query, std::vector<std::uint32_t>& out) const;
  void takeFrom(UniformGrid& other) noexcept;
  static Level buildLevel(std::span<const Aabb2> boxes, std::span<const std::uint32_t> members);
  void refreshViews();
};

/// Brute-force twin of UniformGrid: tests every box. The reference in tests.
class BruteForceBroadPhase {
 public:
  /// Keeps a copy of the boxes.
  explicit BruteForceBroadPhase(std::span<const Aabb2> boxes)
      : boxes_(boxes.begin(), boxes.end()) {}
  /// Same contract as UniformGrid::query.
  void query(const Aabb2& query, std::vector<std::uint32_t>& out) const;

 private:
  std::vector<Aabb2> boxes_;
};

}  // namespace cardemo
