#pragma once
/// Internal to UniformGrid: the cells of a level, and the choice of their shape by the cost of the
/// scans a query makes over them.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/aabb.hpp"

namespace cardemo::grid_detail {

/// Cell index of coordinate `x` on one axis with cells of 1 / inv_cell metres from `origin`,
/// clamped to [0, n): monotone non-decreasing in x, and NaN lands in cell 0.
std::int64_t cellOf(double x, double origin, double inv_cell, std::int64_t n);

/// A level's cells of one shape, and the cell of each member's lower-left corner.
struct CellCounts {
  std::int64_t nx = 0, ny = 0;         ///< Cells along x and y.
  Eigen::Vector2d inv_cell{1.0, 1.0};  ///< 1 / cell width and height, 1/m.
  std::vector<std::uint32_t> cell_of;  ///< Cell (row-major) of members[k].
  std::vector<std::uint32_t> in_cell;  ///< Members in each cell (row-major).
};

/// The cells over `bounds` (whose finite widths are `span`) for the boxes `boxes[members[k]]`,
/// whose extents are at most `reach`: square cells of side `side`, or, for a level of 32,768
/// members or more, cells a quarter as wide and 1.5 times as tall when their estimated scan cost
/// is lower; at most 4 * members + 16 cells and 2^30 along an axis (larger cells otherwise).
CellCounts cheapestCells(std::span<const Aabb2> boxes, std::span<const std::uint32_t> members,
                         const Aabb2& bounds, const Eigen::Vector2d& span,
                         const Eigen::Vector2d& reach, double side);

}  // namespace cardemo::grid_detail
