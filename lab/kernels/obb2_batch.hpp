#pragma once
/// One 2D box against many: struct-of-arrays storage and branchless batch SAT kernels.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/obb2.hpp"
#include "lab/geometry/aligned_allocator.hpp"
#include "lab/kernels/batch_entry.hpp"

namespace cardemo {

/// Many 2D oriented boxes, one array per field (centre x/y, axis x/y, half extents x/y), so the
/// batch kernels load four or eight boxes per instruction, plus a float copy for the boolean
/// query's pre-filter (centres relative to a reference point of the batch). Built once; the
/// queries never allocate.
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
  /// True when every box is within the float pre-filter's range (2^60 m of the reference point).
  [[nodiscard]] bool filterUsable() const { return filter_usable_; }
  /// The float copy for the pre-filter, padded with copies of the last box to whole groups of
  /// sixteen. Only meaningful when filterUsable().
  [[nodiscard]] batch_detail::Box2FilterArrays filterArrays() const;
  /// The point the float centres are relative to, world metres.
  [[nodiscard]] const Eigen::Vector2d& filterReference() const { return reference_; }
  /// Largest |x| + |y| of the float centres, metres (a term of the pre-filter's error bound).
  [[nodiscard]] double filterReach() const { return reach_; }

 private:
  template <class T>
  using Aligned = std::vector<T, AlignedAllocator<T>>;
  Aligned<double> cx_, cy_, ux_, uy_, hx_, hy_;
  Aligned<float> fx_, fy_, fux_, fuy_, fhx_, fhy_, fbound_;
  Eigen::Vector2d reference_ = Eigen::Vector2d::Zero();
  double reach_ = 0.0;
  bool filter_usable_ = false;
};

/// Boolean SAT of `a` against every box of `many`: hit[i] = 1 when they touch or overlap, else 0.
/// Bit-identical to overlapObb2(a, many.box(i)) on every batch path. `hit.size()` must equal
/// `many.size()`. The SIMD paths decide most pairs with a float pre-filter and recompute the
/// near-touching rest in double; returns how many pairs went to that double kernel (0 on the
/// portable path, `many.size()` when the pre-filter cannot be used).
std::size_t overlapObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<std::uint8_t> hit);

/// SAT with separation and normal of `a` against every box of `many`: separation[i] and the unit
/// normal (normal_x[i], normal_y[i]) from A towards box i, bit-identical to collideObb2(a,
/// many.box(i)) on every batch path (hit is separation[i] <= 0). Every span must have
/// `many.size()` entries.
void collideObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<double> separation,
                      std::span<double> normal_x, std::span<double> normal_y);

}  // namespace cardemo
