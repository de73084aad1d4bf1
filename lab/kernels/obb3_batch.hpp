#pragma once
/// One 3D box against many: struct-of-arrays storage and batch SAT kernels.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/obb3.hpp"
#include "lab/geometry/aligned_allocator.hpp"
#include "lab/kernels/batch_entry.hpp"

namespace cardemo {

/// Many 3D oriented boxes, one array per scalar field (centre, the nine rotation entries, half
/// extents), plus a float copy for the boolean query's pre-filter (centres relative to a reference
/// point of the batch). Built once; the queries never allocate.
class Obb3Batch {
 public:
  /// An empty batch.
  Obb3Batch() = default;
  /// A batch holding `boxes` in order (index i is box i).
  explicit Obb3Batch(std::span<const Obb3> boxes);

  /// Number of boxes.
  [[nodiscard]] std::size_t size() const { return center_[0].size(); }
  /// Box i, as stored.
  [[nodiscard]] Obb3 box(std::size_t i) const;
  /// Heap bytes held.
  [[nodiscard]] std::size_t memoryBytes() const;
  /// Raw arrays for the kernels.
  [[nodiscard]] batch_detail::Box3Arrays arrays() const;
  /// Largest departure of a stored rotation from an orthonormal right-handed frame
  /// (cardemo::frameDefect in obb3.hpp); it widens the error bound of the kernels' fast filter.
  [[nodiscard]] double frameDefect() const { return frame_defect_; }
  /// True when every box is within the float pre-filter's range (2^60 m of the reference point).
  [[nodiscard]] bool filterUsable() const { return filter_usable_; }
  /// The float copy for the pre-filter, padded with copies of the last box to whole groups of
  /// sixteen. Only meaningful when filterUsable().
  [[nodiscard]] batch_detail::Box3FilterArrays filterArrays() const;
  /// The point the float centres are relative to, world metres.
  [[nodiscard]] const Eigen::Vector3d& filterReference() const { return reference_; }

 private:
  template <class T>
  using Aligned = std::vector<T, AlignedAllocator<T>>;
  std::array<std::vector<double>, 3> center_;
  std::array<std::vector<double>, 9> rotation_;  // entry 3*j + k: component k of column j
  std::array<std::vector<double>, 3> half_;
  double frame_defect_ = 0.0;
  std::array<Aligned<float>, 3> filter_center_;
  std::array<Aligned<float>, 9> filter_rotation_;
  std::array<Aligned<float>, 3> filter_half_;
  Aligned<float> filter_bound_;
  Eigen::Vector3d reference_ = Eigen::Vector3d::Zero();
  bool filter_usable_ = false;
};

/// 15-axis boolean SAT of `a` against every box of `many`: hit[i] = 1 when they touch or overlap.
/// Same axes as collideObb3 (error-free edge axes in the world frame, exactly parallel edges
/// skipped); equal to `separation <= 0` of separationObb3Batch, on every path. The SIMD paths
/// first decide most pairs in float, eight at a time (a pre-filter with a rigorous error bound);
/// the rest, and every pair on the portable path, go to the double kernel, where a filter in A's
/// frame decides the pairs whose edge gaps clear its error bound and the others take the
/// error-free edge axes, so every verdict is that of the accurate kernel. Returns how many pairs
/// the float pre-filter left to the double kernel (0 on the portable path, `many.size()` when the
/// pre-filter cannot be used).
std::size_t overlapObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<std::uint8_t> hit);

/// 15-axis SAT separation (metres, <= 0 when touching or overlapping) of `a` against every box of
/// `many`. Within 2^-40 (about 1e-12) of the pair's scale (centre offset plus half extents) of the
/// accurate kernel's separation, itself within rounding of collideObb3's; pairs near touching or
/// with edges within about 1.6 degrees of parallel (but not exactly parallel) take the accurate
/// kernel. Bit-identical on both batch paths.
void separationObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<double> separation);

}  // namespace cardemo
