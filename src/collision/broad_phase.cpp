#include "collision/broad_phase.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace cardemo {
namespace {

// An item whose bounds cover more cells than this is kept in a side list that every query tests
// directly: a few huge obstacles would otherwise be copied into thousands of cells each.
constexpr std::int64_t kMaxCellsPerItem = 64;

// Cell index of coordinate `x` on one axis. The index is clamped while still a double, so a huge,
// far-off (or NaN) coordinate can never overflow the integer conversion. The map is monotone, so
// closed intervals that touch map to cell ranges that share a cell.
std::int64_t cellOf(double x, double origin, double inv_cell, std::int64_t n) {
  const double t = std::floor((x - origin) * inv_cell);
  if (!(t > 0.0)) return 0;
  if (t >= static_cast<double>(n - 1)) return n - 1;
  return static_cast<std::int64_t>(t);
}

// Number of cells of size `cell` needed to cover a width `w` (as a double: it may be astronomic).
double cellsAcross(double w, double cell) {
  return std::floor(w / cell) + 1.0;
}

double finiteWidth(double w) {
  return std::isfinite(w) ? w : std::numeric_limits<double>::max();
}

}  // namespace

UniformGrid::UniformGrid(std::span<const Aabb2> boxes)
    : boxes_(boxes.begin(), boxes.end()), stamp_(boxes.size(), 0) {
  const std::size_t n = boxes_.size();
  assert(n < std::numeric_limits<std::uint32_t>::max());
  if (n == 0) {
    cell_start_.assign(1, 0);
    return;
  }
  bounds_ = boxes_[0];
  for (const Aabb2& b : boxes_) bounds_ = bounds_.merged(b);
  const double wx = finiteWidth(bounds_.max.x() - bounds_.min.x());
  const double wy = finiteWidth(bounds_.max.y() - bounds_.min.y());

  // Cell size from the median box extent (Ericson, RTCD 7.1.2: cells about the size of the
  // objects keep both the per-cell lists and the cells per object short).
  std::vector<double> extents(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d s = boxes_[i].size();
    extents[i] = std::max(s.x(), s.y());
  }
  const auto mid = extents.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(extents.begin(), mid, extents.end());
  double cell = *mid;
  if (!(cell > 0.0)) {
    // Degenerate (point) boxes: spread them over about one cell each.
    const double span = std::max(wx, wy);
    cell = span > 0.0 ? span / std::ceil(std::sqrt(static_cast<double>(n))) : 1.0;
  }
  if (!std::isfinite(cell)) cell = std::numeric_limits<double>::max();

  // Memory stays O(N): at most 4N + 16 cells; sparse scenes get larger cells instead.
  const double max_cells = 4.0 * static_cast<double>(n) + 16.0;
  while (cellsAcross(wx, cell) * cellsAcross(wy, cell) > max_cells) cell *= 2.0;
  nx_ = static_cast<std::int64_t>(cellsAcross(wx, cell));
  ny_ = static_cast<std::int64_t>(cellsAcross(wy, cell));
  inv_cell_ = 1.0 / cell;

  // Counting pass, then CSR offsets, then fill (items go in increasing id order per cell).
  const std::size_t cells = static_cast<std::size_t>(nx_ * ny_);
  cell_start_.assign(cells + 1, 0);
  struct Span {
    std::int64_t x0, x1, y0, y1;
  };
  auto spanOf = [&](const Aabb2& b) {
    return Span{cellOf(b.min.x(), bounds_.min.x(), inv_cell_, nx_),
                cellOf(b.max.x(), bounds_.min.x(), inv_cell_, nx_),
                cellOf(b.min.y(), bounds_.min.y(), inv_cell_, ny_),
                cellOf(b.max.y(), bounds_.min.y(), inv_cell_, ny_)};
  };
  auto isLarge = [](const Span& s) {
    return (s.x1 - s.x0 + 1) * (s.y1 - s.y0 + 1) > kMaxCellsPerItem;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Span s = spanOf(boxes_[i]);
    if (isLarge(s)) {
      large_items_.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    for (std::int64_t y = s.y0; y <= s.y1; ++y) {
      for (std::int64_t x = s.x0; x <= s.x1; ++x)
        ++cell_start_[static_cast<std::size_t>(y * nx_ + x) + 1];
    }
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> cursor(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Span s = spanOf(boxes_[i]);
    if (isLarge(s)) continue;
    for (std::int64_t y = s.y0; y <= s.y1; ++y) {
      for (std::int64_t x = s.x0; x <= s.x1; ++x) {
        cell_items_[cursor[static_cast<std::size_t>(y * nx_ + x)]++] =
            static_cast<std::uint32_t>(i);
      }
    }
  }
}

void UniformGrid::query(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  out.clear();
  // Also rejects NaN boxes, since every comparison with NaN is false.
  if (boxes_.empty() || !query.overlaps(bounds_)) return;
  if (++query_number_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    query_number_ = 1;
  }
  const std::int64_t x0 = cellOf(query.min.x(), bounds_.min.x(), inv_cell_, nx_);
  const std::int64_t x1 = cellOf(query.max.x(), bounds_.min.x(), inv_cell_, nx_);
  const std::int64_t y0 = cellOf(query.min.y(), bounds_.min.y(), inv_cell_, ny_);
  const std::int64_t y1 = cellOf(query.max.y(), bounds_.min.y(), inv_cell_, ny_);
  for (std::int64_t y = y0; y <= y1; ++y) {
    for (std::int64_t x = x0; x <= x1; ++x) {
      const std::size_t c = static_cast<std::size_t>(y * nx_ + x);
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t id = cell_items_[k];
        if (stamp_[id] == query_number_) continue;
        stamp_[id] = query_number_;
        if (boxes_[id].overlaps(query)) out.push_back(id);
      }
    }
  }
  for (const std::uint32_t id : large_items_) {
    if (boxes_[id].overlaps(query)) out.push_back(id);
  }
  std::sort(out.begin(), out.end());
}

std::size_t UniformGrid::memoryBytes() const {
  return boxes_.capacity() * sizeof(Aabb2) + (cell_start_.capacity() + cell_items_.capacity() +
                                              stamp_.capacity() + large_items_.capacity()) *
                                                 sizeof(std::uint32_t);
}

void BruteForceBroadPhase::query(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  out.clear();
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (boxes_[i].overlaps(query)) out.push_back(static_cast<std::uint32_t>(i));
  }
}

}  // namespace cardemo
