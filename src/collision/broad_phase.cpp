#include "collision/broad_phase.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cardemo {
namespace {

// Size classes: level k holds boxes whose larger extent is at most base * 4^k (a hierarchical
// grid, Ericson, RTCD 7.2). Anything larger than the last level (or not finite) goes to the list
// of oversized items that every query tests directly.
constexpr int kMaxLevels = 8;
constexpr double kLevelRatio = 4.0;

// Cell side as a share of the side of the average area per box: about two cells per box. Finer
// cells scan fewer boxes that cannot overlap; each costs 4 bytes.
constexpr double kCellScale = 0.7;

// Cell index of coordinate `x` on one axis. The index is clamped while still a double, so a huge,
// far-off (or NaN) coordinate can never overflow the integer conversion. The map is monotone
// non-decreasing in x, which is all the query's correctness argument needs.
std::int64_t cellOf(double x, double origin, double inv_cell, std::int64_t n) {
  // max(0, NaN) is 0 as std::max is written, so NaN lands in cell 0 too. Branch-free.
  const double t = std::min(std::max(0.0, (x - origin) * inv_cell), static_cast<double>(n - 1));
  // t is in [0, n-1] here, so truncation is floor (and needs no libm call on baseline x86-64).
  return static_cast<std::int64_t>(t);
}

// Number of cells of size `cell` needed to cover a width `w` (as a double: it may be astronomic).
double cellsAcross(double w, double cell) {
  return std::floor(w / cell) + 1.0;
}

double finiteWidth(double w) {
  return std::isfinite(w) ? w : std::numeric_limits<double>::max();
}

// Larger side of a box; NaN or infinite for boxes that are.
double extentOf(const Aabb2& b) {
  return std::max(b.max.x() - b.min.x(), b.max.y() - b.min.y());
}

// 1 when the closed boxes b and [qmin, qmax] share a point, else 0; no branches. On x86-64
// (SSE2 is part of the baseline) both axes are compared in one instruction per side.
std::size_t overlapsBranchless(const Aabb2& b, const Eigen::Vector2d& qmin,
                               const Eigen::Vector2d& qmax) {
#if defined(__SSE2__)
  const __m128d below = _mm_cmple_pd(_mm_loadu_pd(b.min.data()), _mm_loadu_pd(qmax.data()));
  const __m128d above = _mm_cmple_pd(_mm_loadu_pd(qmin.data()), _mm_loadu_pd(b.max.data()));
  return static_cast<std::size_t>(_mm_movemask_pd(_mm_and_pd(below, above)) == 3);
#else
  return static_cast<std::size_t>((b.min.x() <= qmax.x()) & (qmin.x() <= b.max.x()) &
                                  (b.min.y() <= qmax.y()) & (qmin.y() <= b.max.y()));
#endif
}

// Sorts ids in place: usually a handful, nearly sorted already.
void sortIds(std::uint32_t* first, std::uint32_t* last) {
  if (last - first > 32) {
    std::sort(first, last);
    return;
  }
  for (std::uint32_t* i = first + 1; i < last; ++i) {
    const std::uint32_t v = *i;
    std::uint32_t* j = i;
    for (; j > first && *(j - 1) > v; --j) *j = *(j - 1);
    *j = v;
  }
}

}  // namespace

UniformGrid::Level UniformGrid::buildLevel(std::span<const Aabb2> boxes,
                                           std::span<const std::uint32_t> members) {
  Level level;
  const std::size_t n = members.size();
  level.bounds = boxes[members[0]];
  level.reach = Eigen::Vector2d::Zero();
  for (const std::uint32_t id : members) {
    const Aabb2& b = boxes[id];
    level.bounds = level.bounds.merged(b);
    level.reach = level.reach.cwiseMax(b.size());
  }
  // Rounded up so that reach >= the exact extent of every box: a box overlapping the query then
  // has its lower corner at or above query.min - reach, however that subtraction rounds (a value
  // <= a double rounds to <= that double), and the monotone cell map keeps the order.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  level.reach = {std::nextafter(level.reach.x(), kInf), std::nextafter(level.reach.y(), kInf)};

  // About two cells per box over the level's bounds. At most 4N + 16 cells: sparse scenes get
  // larger cells instead, so memory stays O(N).
  const double wx = finiteWidth(level.bounds.max.x() - level.bounds.min.x());
  const double wy = finiteWidth(level.bounds.max.y() - level.bounds.min.y());
  double cell = kCellScale * std::sqrt(wx * wy / static_cast<double>(n));
  if (!(cell > 0.0) || !std::isfinite(cell)) {
    // Collinear or coincident boxes: spread them along the longer side.
    const double span = std::max(wx, wy);
    cell = span > 0.0 ? span / static_cast<double>(n) : 1.0;
  }
  const double max_cells = 4.0 * static_cast<double>(n) + 16.0;
  while (cellsAcross(wx, cell) * cellsAcross(wy, cell) > max_cells) cell *= 2.0;
  level.nx = static_cast<std::int64_t>(cellsAcross(wx, cell));
  level.ny = static_cast<std::int64_t>(cellsAcross(wy, cell));
  level.inv_cell = 1.0 / cell;

  // Counting sort by the cell of the lower-left corner; members come in increasing id order, so
  // each cell's ids stay increasing.
  const std::size_t cells = static_cast<std::size_t>(level.nx * level.ny);
  level.cell_start.assign(cells + 1, 0);
  std::vector<std::uint32_t> cell_of(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Aabb2& b = boxes[members[k]];
    const std::int64_t cx = cellOf(b.min.x(), level.bounds.min.x(), level.inv_cell, level.nx);
    const std::int64_t cy = cellOf(b.min.y(), level.bounds.min.y(), level.inv_cell, level.ny);
    cell_of[k] = static_cast<std::uint32_t>(cy * level.nx + cx);
    ++level.cell_start[cell_of[k] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) level.cell_start[c + 1] += level.cell_start[c];
  level.boxes.resize(n);
  level.ids.resize(n);
  std::vector<std::uint32_t> cursor(level.cell_start.begin(), level.cell_start.end() - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t slot = cursor[cell_of[k]]++;
    level.boxes[slot] = boxes[members[k]];
    level.ids[slot] = members[k];
  }
  return level;
}

UniformGrid::UniformGrid(std::span<const Aabb2> boxes) : size_(boxes.size()) {
  const std::size_t n = boxes.size();
  assert(n < std::numeric_limits<std::uint32_t>::max());
  if (n == 0) return;
  bounds_ = boxes[0];
  for (const Aabb2& b : boxes) bounds_ = bounds_.merged(b);

  // Base size class: twice the median extent (Ericson, RTCD 7.1.2: cells about the size of the
  // objects), so a lot of similar cars is one level.
  std::vector<double> extents(n);
  for (std::size_t i = 0; i < n; ++i) extents[i] = extentOf(boxes[i]);
  std::vector<double> sorted = extents;
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(sorted.begin(), mid, sorted.end(),
                   [](double x, double y) { return x < y || (x == x && y != y); });
  double base = 2.0 * *mid;
  if (!(base > 0.0) || !std::isfinite(base)) {
    // Mostly points, or mostly unbounded: spread over about one cell per item.
    const double span = std::max(finiteWidth(bounds_.max.x() - bounds_.min.x()),
                                 finiteWidth(bounds_.max.y() - bounds_.min.y()));
    base = span > 0.0 ? span / std::ceil(std::sqrt(static_cast<double>(n))) : 1.0;
  }

  std::array<std::vector<std::uint32_t>, kMaxLevels> members;
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = static_cast<std::uint32_t>(i);
    double limit = base;
    int k = 0;
    while (k < kMaxLevels && !(extents[i] <= limit)) {
      limit *= kLevelRatio;
      ++k;
    }
    if (k < kMaxLevels) {
      members[static_cast<std::size_t>(k)].push_back(id);
    } else {
      large_boxes_.push_back(boxes[i]);
      large_ids_.push_back(id);
    }
  }
  for (const std::vector<std::uint32_t>& m : members) {
    if (!m.empty()) levels_.push_back(buildLevel(boxes, m));
  }
}

void UniformGrid::Collector::spill() {
  out.insert(out.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(count));
  count = 0;
}

void UniformGrid::Collector::finish() {
  if (out.empty()) {
    // The common case: everything fit in the buffer. Sort there, copy once.
    sortIds(buffer.data(), buffer.data() + count);
    out.assign(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(count));
    return;
  }
  spill();
  sortIds(out.data(), out.data() + out.size());
}

void UniformGrid::queryLevel(const Level& level, const Aabb2& query, Collector& found) {
  if (!query.overlaps(level.bounds)) return;
  const Eigen::Vector2d& o = level.bounds.min;
  const std::int64_t x0 = cellOf(query.min.x() - level.reach.x(), o.x(), level.inv_cell, level.nx);
  const std::int64_t x1 = cellOf(query.max.x(), o.x(), level.inv_cell, level.nx);
  const std::int64_t y0 = cellOf(query.min.y() - level.reach.y(), o.y(), level.inv_cell, level.ny);
  const std::int64_t y1 = cellOf(query.max.y(), o.y(), level.inv_cell, level.ny);
  const std::uint32_t* start = level.cell_start.data();
  const Aabb2* boxes = level.boxes.data();
  const std::uint32_t* ids = level.ids.data();
  const Eigen::Vector2d qmin = query.min, qmax = query.max;
  for (std::int64_t y = y0; y <= y1; ++y) {
    // The cells x0..x1 of a row are adjacent, so their boxes form one contiguous run.
    const std::uint32_t begin = start[y * level.nx + x0];
    const std::uint32_t end = start[y * level.nx + x1 + 1];
    if (end - begin > found.room()) {
      found.spill();
      if (end - begin > found.room()) {
        // A run longer than the whole buffer (a very dense or very sparse lot): no shortcuts.
        for (std::uint32_t k = begin; k < end; ++k) {
          if (boxes[k].overlaps(query)) found.add(ids[k]);
        }
        continue;
      }
    }
    // Branchless filter: every id is written, and the count advances only past the overlapping
    // ones (an overlap test per box is a coin flip that a branch would mispredict).
    std::uint32_t* dst = found.buffer.data();
    std::size_t n = found.count;
    for (std::uint32_t k = begin; k < end; ++k) {
      dst[n] = ids[k];
      n += overlapsBranchless(boxes[k], qmin, qmax);
    }
    found.count = n;
  }
}

void UniformGrid::query(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  out.clear();
  // Also rejects NaN boxes, since every comparison with NaN is false.
  if (size_ == 0 || !query.overlaps(bounds_)) return;
  Collector found(out);
  for (const Level& level : levels_) queryLevel(level, query, found);
  for (std::size_t k = 0; k < large_boxes_.size(); ++k) {
    if (large_boxes_[k].overlaps(query)) found.add(large_ids_[k]);
  }
  found.finish();
}

std::size_t UniformGrid::memoryBytes() const {
  std::size_t bytes = levels_.capacity() * sizeof(Level) + large_boxes_.capacity() * sizeof(Aabb2) +
                      large_ids_.capacity() * sizeof(std::uint32_t);
  for (const Level& level : levels_) {
    bytes += level.boxes.capacity() * sizeof(Aabb2) +
             (level.cell_start.capacity() + level.ids.capacity()) * sizeof(std::uint32_t);
  }
  return bytes;
}

void BruteForceBroadPhase::query(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  out.clear();
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (boxes_[i].overlaps(query)) out.push_back(static_cast<std::uint32_t>(i));
  }
}

}  // namespace cardemo
