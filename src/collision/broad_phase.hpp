#pragma once
/// Static broad phase over the parked cars and obstacles: a uniform grid built once.

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/aabb.hpp"

namespace cardemo {

/// Uniform grid in compressed-sparse-row form over static boxes. Build is O(N); a query visits only
/// the cells its box overlaps, so its cost does not grow with the number of parked cars.
class UniformGrid {
 public:
  /// Builds the grid over `boxes` (index i of the span is the item id). The cell size follows the
  /// typical box size; the grid covers the union of the boxes. An empty span is allowed.
  explicit UniformGrid(std::span<const Aabb2> boxes);

  /// Appends to `out` (after clearing it) the ids of every box that touches or overlaps `query`,
  /// each once, in increasing id order. Does not allocate once `out` has grown to its peak size.
  void query(const Aabb2& query, std::vector<std::uint32_t>& out) const;

  /// Number of items the grid was built over.
  [[nodiscard]] std::size_t size() const { return boxes_.size(); }
  /// Heap bytes held by the structure (for bytes-per-car reports).
  [[nodiscard]] std::size_t memoryBytes() const;

 private:
  std::vector<Aabb2> boxes_;
  Aabb2 bounds_;
  double inv_cell_ = 1.0;
  std::int64_t nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_start_;  // nx*ny+1 offsets into cell_items_
  std::vector<std::uint32_t> cell_items_;
  std::vector<std::uint32_t> large_items_;  // items spanning too many cells: tested by every query
  mutable std::vector<std::uint32_t> stamp_;  // last query number that reported item i
  mutable std::uint32_t query_number_ = 0;
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
