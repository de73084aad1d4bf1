// The cell shape of a level: see docs/architecture.md, "Broad phase".

#include "collision/grid_cells.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

namespace cardemo::grid_detail {
namespace {

// At most 2^30 cells along an axis, so a cell index fits the 32-bit lanes of the query's packed
// conversion (and any row's first cell index fits 64 bits).
constexpr double kMaxCellsPerAxis = 0x1p30;

// Number of cells of size `cell` needed to cover a width `w` (as a double: it may be astronomic).
double cellsAcross(double w, double cell) {
  return std::floor(w / cell) + 1.0;
}

// A cell shape, as multiples of the square cell's side.
struct CellShape {
  double width, height;
};
// Square first, so that it wins a tie. A query scans each row of its window as one run of boxes:
// taller cells mean fewer rows, narrower ones fewer boxes left of the window in each row. Which
// costs less depends on the layout.
constexpr CellShape kCellShapes[] = {{1.0, 1.0}, {0.25, 1.5}};

// Levels with fewer members keep square cells: there the estimate would cost more than the build
// (a build of 1,000 cars took twice as long with it), and a query saves a few per cent at most.
constexpr std::size_t kMinMembersToChoose = 32768;

CellCounts countCells(std::span<const Aabb2> boxes, std::span<const std::uint32_t> members,
                      const Aabb2& bounds, std::int64_t nx, std::int64_t ny,
                      const Eigen::Vector2d& inv_cell) {
  CellCounts counts{nx, ny, inv_cell, std::vector<std::uint32_t>(members.size()),
                    std::vector<std::uint32_t>(static_cast<std::size_t>(nx * ny), 0)};
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Aabb2& b = boxes[members[k]];
    const std::int64_t cx = cellOf(b.min.x(), bounds.min.x(), inv_cell.x(), nx);
    const std::int64_t cy = cellOf(b.min.y(), bounds.min.y(), inv_cell.y(), ny);
    counts.cell_of[k] = static_cast<std::uint32_t>(cy * nx + cx);
    ++counts.in_cell[counts.cell_of[k]];
  }
  return counts;
}

// Relative costs of a query's scan (instructions counted with callgrind): about 9 for
// each occupied row of its window and 18 for each step of four boxes (at least one a row).
constexpr double kRowCost = 9.0, kStepCost = 18.0;
// Members placed in cells for the estimate: all up to this many, else an even subsample of about
// this many, each standing for the members it skips.
constexpr std::size_t kCountedMembers = 16384;

// Queries for the estimate.
constexpr std::size_t kCostQueries = 1024;

// One cell shape: nx by ny cells of 1 / inv_cell metres.
struct CellGrid {
  std::int64_t nx, ny;
  Eigen::Vector2d inv_cell;
};

// The summed scan cost of kCostQueries queries the size of the level's boxes (a car among parked
// cars), placed evenly over its bounds (finite widths `span`), as a moving car meets aisles and
// rows in proportion to their area.
double estimatedScanCost(const CellGrid& grid, std::span<const Aabb2> boxes,
                         std::span<const std::uint32_t> members, const Aabb2& bounds,
                         const Eigen::Vector2d& span, const Eigen::Vector2d& reach) {
  const std::size_t n = members.size();
  const std::size_t nx = static_cast<std::size_t>(grid.nx);
  const std::size_t ny = static_cast<std::size_t>(grid.ny);
  const auto cell = [&](double at, int axis, std::int64_t cells) {
    return static_cast<std::size_t>(cellOf(at, bounds.min[axis], grid.inv_cell[axis], cells));
  };
  // Counted members in cells [0, x) of each row: prefix[row * (nx + 1) + x].
  const std::size_t stride = std::max<std::size_t>(1, n / kCountedMembers);
  std::vector<std::uint32_t> prefix(ny * (nx + 1), 0);
  for (std::size_t k = 0; k < n; k += stride) {
    const Aabb2& b = boxes[members[k]];
    ++prefix[cell(b.min.y(), 1, grid.ny) * (nx + 1) + cell(b.min.x(), 0, grid.nx) + 1];
  }
  for (std::size_t row = 0; row < ny; ++row) {
    std::uint32_t* p = &prefix[row * (nx + 1)];
    for (std::size_t x = 0; x < nx; ++x) p[x + 1] += p[x];
  }
  // Places from the R2 sequence (M. Roberts, "The unreasonable effectiveness of quasirandom
  // sequences", 2018): low discrepancy, no seed; sizes from members spread through the level.
  const std::size_t queries = kCostQueries;
  double u = 0.5, v = 0.5, cost = 0.0;
  for (std::size_t i = 0; i < queries; ++i) {
    u += 0.7548776662466927;
    v += 0.5698402909980532;
    u -= u >= 1.0 ? 1.0 : 0.0;
    v -= v >= 1.0 ? 1.0 : 0.0;
    const Eigen::Vector2d half = 0.5 * boxes[members[i * n / queries]].size();
    const Eigen::Vector2d centre = bounds.min + Eigen::Vector2d(u * span.x(), v * span.y());
    const std::size_t x0 = cell(centre.x() - half.x() - reach.x(), 0, grid.nx);
    const std::size_t x1 = cell(centre.x() + half.x(), 0, grid.nx);
    const std::size_t y0 = cell(centre.y() - half.y() - reach.y(), 1, grid.ny);
    const std::size_t y1 = cell(centre.y() + half.y(), 1, grid.ny);
    for (std::size_t row = y0; row <= y1; ++row) {
      const std::uint32_t* p = &prefix[row * (nx + 1)];
      if (p[nx] == 0) continue;  // an empty row costs no step
      const double in_window = static_cast<double>((p[x1 + 1] - p[x0]) * stride);
      cost += kRowCost + kStepCost * std::max(1.0, std::ceil(in_window / 4.0));
    }
  }
  return cost;
}

}  // namespace

// Clamped while still a double, so a huge, far-off (or NaN) coordinate can never overflow the
// integer conversion. Monotone, which is all the query's correctness argument needs.
std::int64_t cellOf(double x, double origin, double inv_cell, std::int64_t n) {
  // max(0, NaN) is 0 as std::max is written, so NaN lands in cell 0 too. Branch-free.
  const double t = std::min(std::max(0.0, (x - origin) * inv_cell), static_cast<double>(n - 1));
  // t is in [0, n-1] here, so truncation is floor (and needs no libm call on baseline x86-64).
  return static_cast<std::int64_t>(t);
}

CellCounts cheapestCells(std::span<const Aabb2> boxes, std::span<const std::uint32_t> members,
                         const Aabb2& bounds, const Eigen::Vector2d& span,
                         const Eigen::Vector2d& reach, double side) {
  const double max_cells = 4.0 * static_cast<double>(members.size()) + 16.0;
  const std::size_t shapes = members.size() >= kMinMembersToChoose ? std::size(kCellShapes) : 1;
  CellGrid best{};
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shapes; ++i) {
    const CellShape& shape = kCellShapes[i];
    double cell_x = side * shape.width, cell_y = side * shape.height;
    // A side near the smallest double (boxes of no extent) can underflow to 0; square cells stay.
    if (!(cell_x > 0.0) || !(cell_y > 0.0)) continue;
    // Sparse scenes get larger cells, so memory stays O(N).
    while (cellsAcross(span.x(), cell_x) * cellsAcross(span.y(), cell_y) > max_cells ||
           std::max(cellsAcross(span.x(), cell_x), cellsAcross(span.y(), cell_y)) >
               kMaxCellsPerAxis) {
      cell_x *= 2.0;
      cell_y *= 2.0;
    }
    const CellGrid grid{static_cast<std::int64_t>(cellsAcross(span.x(), cell_x)),
                        static_cast<std::int64_t>(cellsAcross(span.y(), cell_y)),
                        {1.0 / cell_x, 1.0 / cell_y}};
    const double cost =
        shapes == 1 ? 0.0 : estimatedScanCost(grid, boxes, members, bounds, span, reach);
    if (cost < best_cost) {
      best_cost = cost;
      best = grid;
    }
  }
  return countCells(boxes, members, bounds, best.nx, best.ny, best.inv_cell);
}

}  // namespace cardemo::grid_detail
