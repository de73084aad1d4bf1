// The cell shape of a level: see docs/architecture.md, "Broad phase".

#include "collision/grid_cells.hpp"

#include <algorithm>
#include <cmath>
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
// costs less depends on the layout (docs/perf/history.md, "Broad-phase query").
constexpr CellShape kCellShapes[] = {{1.0, 1.0}, {0.5, 1.25}, {0.25, 1.5}};

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

// Relative costs of a query's scan (callgrind, docs/perf/history.md): about 9 instructions for
// each occupied row of its window and 18 for each step of four boxes (at least one a row).
constexpr double kRowCost = 9.0, kStepCost = 18.0;
// Queries sampled for the estimate: about this many of the level's boxes, evenly spaced.
constexpr std::size_t kCostSamples = 1024;

// The summed scan cost of about kCostSamples queries the size of the level's boxes (a car among
// parked cars), placed evenly over its bounds (finite widths `span`), as a moving car meets aisles
// and rows in proportion to their area.
double estimatedScanCost(const CellCounts& counts, std::span<const Aabb2> boxes,
                         std::span<const std::uint32_t> members, const Aabb2& bounds,
                         const Eigen::Vector2d& span, const Eigen::Vector2d& reach) {
  const std::size_t nx = static_cast<std::size_t>(counts.nx);
  const std::size_t ny = static_cast<std::size_t>(counts.ny);
  // Members in cells [0, x) of each row: prefix[row * (nx + 1) + x].
  std::vector<std::uint32_t> prefix(ny * (nx + 1), 0);
  for (std::size_t row = 0; row < ny; ++row) {
    for (std::size_t x = 0; x < nx; ++x) {
      prefix[row * (nx + 1) + x + 1] = prefix[row * (nx + 1) + x] + counts.in_cell[row * nx + x];
    }
  }
  // Sizes from members spread evenly through the level, places from the R2 sequence (M. Roberts,
  // "The unreasonable effectiveness of quasirandom sequences", 2018): low discrepancy, no seed.
  const std::size_t stride = std::max<std::size_t>(1, members.size() / kCostSamples);
  double cost = 0.0;
  for (std::size_t k = 0, i = 0; k < members.size(); k += stride, ++i) {
    const Eigen::Vector2d half = 0.5 * boxes[members[k]].size();
    const double u = std::fmod(0.5 + 0.7548776662466927 * static_cast<double>(i), 1.0);
    const double v = std::fmod(0.5 + 0.5698402909980532 * static_cast<double>(i), 1.0);
    const Eigen::Vector2d centre = bounds.min + Eigen::Vector2d(u * span.x(), v * span.y());
    const Aabb2 q{centre - half, centre + half};
    const auto cell = [&](double at, int axis, std::int64_t n) {
      return static_cast<std::size_t>(cellOf(at, bounds.min[axis], counts.inv_cell[axis], n));
    };
    const std::size_t x0 = cell(q.min.x() - reach.x(), 0, counts.nx);
    const std::size_t x1 = cell(q.max.x(), 0, counts.nx);
    const std::size_t y0 = cell(q.min.y() - reach.y(), 1, counts.ny);
    const std::size_t y1 = cell(q.max.y(), 1, counts.ny);
    for (std::size_t row = y0; row <= y1; ++row) {
      const std::uint32_t* p = &prefix[row * (nx + 1)];
      if (p[nx] == 0) continue;  // an empty row costs no step
      const std::uint32_t in_window = p[x1 + 1] - p[x0];
      cost += kRowCost + kStepCost * std::max<double>(1.0, std::ceil(in_window / 4.0));
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
  CellCounts best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const CellShape& shape : kCellShapes) {
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
    CellCounts counts = countCells(
        boxes, members, bounds, static_cast<std::int64_t>(cellsAcross(span.x(), cell_x)),
        static_cast<std::int64_t>(cellsAcross(span.y(), cell_y)), {1.0 / cell_x, 1.0 / cell_y});
    const double cost = estimatedScanCost(counts, boxes, members, bounds, span, reach);
    if (cost < best_cost) {
      best_cost = cost;
      best = std::move(counts);
    }
  }
  return best;
}

}  // namespace cardemo::grid_detail
