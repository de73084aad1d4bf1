#pragma once
/// One 2D box against many: struct-of-arrays storage and branchless batch SAT kernels.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/batch_entry.hpp"
#include "geometry/obb2.hpp"

namespace cardemo {

/// Many 2D oriented boxes, one array per field (centre x/y, axis x/y, half extents x/y), so the
/// batch kernels load four boxes per instruction. Built once; the queries never allocate.
class Obb2Batch {
 public:
  /// An empty batch.
  Obb2Batch() = default;
  /// A batch holding `boxes` in order (index i is box i).
  explicit Obb2Batch(std::span<const Obb2> boxes);

  /// Number of boxes.
  [[nodiscard]] std::size_t size() const { return cx_.size(); }
  /// Box i, as stored.
  [[nodiscard]] Obb2 box(std::size_t i) const;
  /// Heap bytes held.
  [[nodiscard]] std::size_t memoryBytes() const;
  /// Raw arrays for the kernels.
  [[nodiscard]] batch_detail::Box2Arrays arrays() const;

 private:
  std::vector<double> cx_, cy_, ux_, uy_, hx_, hy_;
};

/// Boolean SAT of `a` against every box of `many`: hit[i] = 1 when they touch or overlap, else 0.
/// Bit-identical to overlapObb2(a, many.box(i)) on either batch path. `hit.size()` must equal
/// `many.size()`.
void overlapObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<std::uint8_t> hit);

/// SAT with separation and normal of `a` against every box of `many`: separation[i] and the unit
/// normal (normal_x[i], normal_y[i]) from A towards box i, bit-identical to collideObb2(a,
/// many.box(i)) on either batch path (hit is separation[i] <= 0). Every span must have
/// `many.size()` entries.
void collideObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<double> separation,
                      std::span<double> normal_x, std::span<double> normal_y);

}  // namespace cardemo
