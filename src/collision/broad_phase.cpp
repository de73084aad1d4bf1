#include "collision/broad_phase.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "collision/grid_cells.hpp"
#include "geometry/batch_path.hpp"

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

double finiteWidth(double w) {
  return std::isfinite(w) ? w : std::numeric_limits<double>::max();
}

// Larger side of a box; NaN or infinite for boxes that are.
double extentOf(const Aabb2& b) {
  return std::max(b.max.x() - b.min.x(), b.max.y() - b.min.y());
}

// Sorts ids in place: usually a handful, nearly sorted already.
[[gnu::always_inline]] inline void sortIds(std::uint32_t* first, std::uint32_t* last) {
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

// Ids found by a query are gathered on the stack, then sorted and appended to the caller's
// vector once; a query that finds more spills the buffer into the vector as it goes.
constexpr std::size_t kQueryBuffer = 128;

void spillInto(grid_detail::IdSink& sink) {
  auto& out = *static_cast<std::vector<std::uint32_t>*>(sink.owner);
  out.insert(out.end(), sink.buffer, sink.buffer + sink.count);
  sink.count = 0;
}

// Out of line and cold, so that the common query keeps a small frame.
[[gnu::noinline, gnu::cold]] void growToFewIds(std::vector<std::uint32_t>& storage) {
  storage.resize(grid_detail::kFewIds);
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
  // No smaller than the boxes' mean reach: a window spans the query plus the reach, so smaller
  // cells add rows (each a bit scan and a step) without leaving out boxes.
  cell = std::max(cell, 0.5 * (level.reach.x() + level.reach.y()));
  if (!(cell > 0.0) || !std::isfinite(cell)) {
    // Collinear or coincident boxes: spread them along the longer side.
    const double span = std::max(wx, wy);
    cell = span > 0.0 ? span / static_cast<double>(n) : 1.0;
  }
  // The shape of cells whose scans cost least (grid_cells.hpp), and each member's cell.
  grid_detail::CellCounts best =
      grid_detail::cheapestCells(boxes, members, level.bounds, {wx, wy}, level.reach, cell);
  level.nx = best.nx;
  level.ny = best.ny;
  level.inv_cell = best.inv_cell;
  const std::size_t nx = static_cast<std::size_t>(level.nx);
  const std::size_t ny = static_cast<std::size_t>(level.ny);
  const std::vector<std::uint32_t>& cell_of = best.cell_of;
  // Each cell's count becomes its cursor: the slot its next member goes to.
  std::vector<std::uint32_t>& cursor = best.in_cell;
  // Row by row: each row's cell offsets and its end (nx + 1 entries), and after the boxes of each
  // occupied row, kRowPadding boxes that nothing finds, so a scan step may read past a row's end
  // without a mask.
  level.cell_start.assign(ny * (nx + 1), 0);
  level.row_bits.assign((ny + 63) / 64 + 1, 0);  // + a zero word past the last row's
  std::size_t slots = 0;
  for (std::size_t row = 0; row < ny; ++row) {
    const std::size_t row_first = slots;
    for (std::size_t c = 0; c < nx; ++c) {
      level.cell_start[row * (nx + 1) + c] = static_cast<std::uint32_t>(slots);
      const std::uint32_t in_cell = cursor[row * nx + c];
      cursor[row * nx + c] = static_cast<std::uint32_t>(slots);
      slots += in_cell;
    }
    level.cell_start[row * (nx + 1) + nx] = static_cast<std::uint32_t>(slots);
    if (slots > row_first) {
      level.row_bits[row / 64] |= std::uint64_t{1} << (row % 64);
      slots += grid_detail::kRowPadding;
    }
  }
  // Every slot index fits the 32-bit offsets.
  assert(slots <= std::numeric_limits<std::uint32_t>::max());
  // NaN boxes: every ordered comparison with them is false, whatever the query.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::size_t stored = slots;
  level.min_x.assign(stored, kNaN);
  level.min_y.assign(stored, kNaN);
  level.max_x.assign(stored, kNaN);
  level.max_y.assign(stored, kNaN);
  level.ids.assign(stored, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t slot = cursor[cell_of[k]]++;
    const Aabb2& b = boxes[members[k]];
    level.min_x[slot] = b.min.x();
    level.min_y[slot] = b.min.y();
    level.max_x[slot] = b.max.x();
    level.max_y[slot] = b.max.y();
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
  refreshViews();
}

UniformGrid::UniformGrid(const UniformGrid& other)
    : size_(other.size_),
      bounds_(other.bounds_),
      levels_(other.levels_),
      large_boxes_(other.large_boxes_),
      large_ids_(other.large_ids_) {
  refreshViews();
}

UniformGrid& UniformGrid::operator=(const UniformGrid& other) {
  if (this != &other) *this = UniformGrid(other);
  return *this;
}

UniformGrid::UniformGrid(UniformGrid&& other) noexcept {
  takeFrom(other);
}

UniformGrid& UniformGrid::operator=(UniformGrid&& other) noexcept {
  if (this != &other) takeFrom(other);
  return *this;
}

void UniformGrid::takeFrom(UniformGrid& other) noexcept {
  // The arrays keep their addresses, so the views stay valid. `other` is left with no level and
  // no item (a defaulted move would leave it a level count over no views).
  size_ = std::exchange(other.size_, 0);
  bounds_ = other.bounds_;
  levels_ = std::exchange(other.levels_, {});
  views_ = std::exchange(other.views_, {});
  level_count_ = std::exchange(other.level_count_, 0);
  scan_few_ = other.scan_few_;
  large_boxes_ = std::exchange(other.large_boxes_, {});
  large_ids_ = std::exchange(other.large_ids_, {});
}

void UniformGrid::refreshViews() {
  views_.clear();
  for (const Level& l : levels_) {
    views_.push_back({l.min_x.data(),
                      l.min_y.data(),
                      l.max_x.data(),
                      l.max_y.data(),
                      l.ids.data(),
                      l.cell_start.data(),
                      l.row_bits.data(),
                      {l.bounds.min.x(), l.bounds.min.y()},
                      {l.bounds.max.x(), l.bounds.max.y()},
                      {l.reach.x(), l.reach.y()},
                      {l.inv_cell.x(), l.inv_cell.y()},
                      {static_cast<double>(l.nx - 1), static_cast<double>(l.ny - 1)},
                      l.nx + 1});
  }
  level_count_ = views_.size();
#if defined(CARDEMO_BATCH_AVX2)
  scan_few_ = large_boxes_.empty() ? &grid_detail::scanFewAvx2 : nullptr;
#endif
}

std::size_t UniformGrid::queryFew(const Aabb2& query, std::uint32_t* few) const {
  // A handful of ids, found and sorted in registers (an empty grid has no levels, and a query off
  // every level's bounds or NaN finds nothing).
  if (scansFew()) {
    return scan_few_(views_.data(), level_count_, query.min.data(), query.max.data(), few);
  }
  return grid_detail::kFewIds + 1;
}

void UniformGrid::query(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  std::array<std::uint32_t, grid_detail::kFewIds> few;
  const std::size_t count = queryFew(query, few.data());
  if (count <= few.size()) [[likely]] {
    // Handed over as a fixed eight, with no branch on how many, then cut to the count.
    out.clear();
    out.resize(few.size());
    std::memcpy(out.data(), few.data(), sizeof few);
    out.resize(count);
    return;
  }
  queryBuffered(query, out);
}

[[gnu::noinline]] void UniformGrid::queryCrowded(const Aabb2& query, QueryIds& out) const {
  queryBuffered(query, out.storage_);
  out.count_ = out.storage_.size();
  if (out.storage_.size() < grid_detail::kFewIds) growToFewIds(out.storage_);
}

void UniformGrid::queryBuffered(const Aabb2& query, std::vector<std::uint32_t>& out) const {
  out.clear();
  // Also rejects NaN boxes, since every comparison with NaN is false.
  if (size_ == 0 || !query.overlaps(bounds_)) return;
  const grid_detail::QueryBox box{{query.min.x(), query.min.y()}, {query.max.x(), query.max.y()}};
  std::array<std::uint32_t, kQueryBuffer> buffer;  // deliberately not zeroed: written before read
  grid_detail::IdSink sink{buffer.data(), buffer.size(), 0, &spillInto, &out};
#if defined(CARDEMO_BATCH_AVX2)
  if (batchPath() != BatchPath::kPortable) {
    grid_detail::scanLevelsAvx2(views_.data(), views_.size(), box, sink);
  } else {
    grid_detail::scanLevelsPortable(views_.data(), views_.size(), box, sink);
  }
#else
  grid_detail::scanLevelsPortable(views_.data(), views_.size(), box, sink);
#endif
  for (std::size_t k = 0; k < large_boxes_.size(); ++k) {
    if (!large_boxes_[k].overlaps(query)) continue;
    if (sink.count == sink.capacity) spillInto(sink);
    buffer[sink.count++] = large_ids_[k];
  }
  if (!out.empty()) {
    // A crowded query spilled: sort everything where it ended up.
    spillInto(sink);
    sortIds(out.data(), out.data() + out.size());
    return;
  }
  // Everything fit in the buffer. Sort there, then append one by one (for a handful of ids
  // cheaper than a call to memmove); `out` keeps its capacity between queries.
  sortIds(buffer.data(), buffer.data() + sink.count);
  if (out.capacity() < sink.count) out.reserve(sink.count);
  for (std::size_t k = 0; k < sink.count; ++k) out.push_back(buffer[k]);
}

std::size_t UniformGrid::memoryBytes() const {
  std::size_t bytes =
      levels_.capacity() * sizeof(Level) + views_.capacity() * sizeof(grid_detail::LevelArrays) +
      large_boxes_.capacity() * sizeof(Aabb2) + large_ids_.capacity() * sizeof(std::uint32_t);
  for (const Level& level : levels_) {
    bytes += (level.min_x.capacity() + level.min_y.capacity() + level.max_x.capacity() +
              level.max_y.capacity()) *
                 sizeof(double) +
             (level.cell_start.capacity() + level.ids.capacity()) * sizeof(std::uint32_t) +
             level.row_bits.capacity() * sizeof(std::uint64_t);
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
