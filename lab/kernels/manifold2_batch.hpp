#pragma once
/// Contact manifolds of many box pairs at once: struct-of-arrays input and output, four pairs per
/// AVX2 instruction or eight per AVX-512 one, the same bits as manifoldObb2.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lab/geometry/aligned_allocator.hpp"
#include "lab/kernels/batch_entry.hpp"
#include "lab/kernels/manifold2.hpp"
#include "lab/kernels/obb2_batch.hpp"

namespace cardemo {

/// The manifolds of a batch of pairs, one array per field, so that the kernel stores a lane
/// group's values with one instruction. Entry i is pair i's manifold; manifold(i) assembles it.
class Manifold2Batch {
 public:
  /// Room for `n` manifolds (contents unspecified until a query writes them).
  void resize(std::size_t n);
  /// Number of manifolds.
  [[nodiscard]] std::size_t size() const { return count_.size(); }
  /// Manifold i as manifoldObb2 returns it (points past its count are default-constructed).
  [[nodiscard]] Manifold2 manifold(std::size_t i) const;
  /// The kernels' view of the arrays.
  [[nodiscard]] batch_detail::Manifold2Out arrays();

 private:
  template <class T>
  using Aligned = std::vector<T, AlignedAllocator<T>>;
  Aligned<double> nx_, ny_, p0x_, p0y_, p1x_, p1y_, separation0_, separation1_;
  Aligned<std::int32_t> feature0_, feature1_, count_, reference_face_;
};

/// out.manifold(i) = manifoldObb2(a.box(i), b.box(i), settings) for every i, with no previous
/// reference face (a first contact), bit for bit on every batch path. `a` and `b` must have the
/// same size; `out` is resized to it. The AVX2 and AVX-512 paths run four and eight pairs per
/// instruction without a branch on any pair's geometry; the portable path calls manifoldObb2.
void manifoldObb2Batch(const Obb2Batch& a, const Obb2Batch& b, Manifold2Batch& out,
                       const ManifoldSettings& settings = {});

}  // namespace cardemo
