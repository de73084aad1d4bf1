#pragma once
/// One 3D box against many: struct-of-arrays storage and branchless batch SAT kernels.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/batch_entry.hpp"
#include "geometry/obb3.hpp"

namespace cardemo {

/// Many 3D oriented boxes, one array per scalar field (centre, the nine rotation entries, half
/// extents). Built once; the queries never allocate.
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

 private:
  std::array<std::vector<double>, 3> center_;
  std::array<std::vector<double>, 9> rotation_;  // entry 3*j + k: component k of column j
  std::array<std::vector<double>, 3> half_;
};

/// 15-axis boolean SAT of `a` against every box of `many`: hit[i] = 1 when they touch or overlap.
/// Same axes as collideObb3 (error-free edge axes in the world frame, exactly parallel edges
/// skipped); equal to `separation <= 0` of separationObb3Batch bit for bit, on either path.
void overlapObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<std::uint8_t> hit);

/// 15-axis SAT separation (metres, <= 0 when touching or overlapping) of `a` against every box of
/// `many`. Agrees with collideObb3's separation to rounding (about 1e-15 relative to the boxes'
/// size and offset); bit-identical on both batch paths.
void separationObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<double> separation);

}  // namespace cardemo
