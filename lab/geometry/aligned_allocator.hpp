#pragma once
/// A standard allocator whose blocks start on a cache-line boundary, for arrays that SIMD kernels
/// load a whole register at a time.

#include <cstddef>
#include <new>

namespace cardemo {

/// std::allocator with `kAlign`-byte aligned blocks (64: one cache line, one AVX-512 register), so
/// a vector load at a multiple of the register width never straddles two cache lines.
template <class T, std::size_t kAlign = 64>
struct AlignedAllocator {
  using value_type = T;  ///< Element type.

  /// Same allocator for another element type (containers rebind).
  template <class U>
  struct rebind {
    using other = AlignedAllocator<U, kAlign>;  ///< The rebound allocator.
  };

  /// Stateless: every instance is interchangeable.
  AlignedAllocator() = default;
  /// Converting copy (stateless).
  template <class U>
  explicit AlignedAllocator(const AlignedAllocator<U, kAlign>& /*other*/) {}

  /// Storage for `n` elements, aligned to kAlign bytes; throws std::bad_alloc like std::allocator.
  [[nodiscard]] T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{kAlign}));
  }
  /// Releases storage from allocate.
  void deallocate(T* p, std::size_t /*n*/) { ::operator delete (p, std::align_val_t{kAlign}); }

  /// Stateless allocators always compare equal.
  template <class U>
  bool operator==(const AlignedAllocator<U, kAlign>& /*other*/) const {
    return true;
  }
};

}  // namespace cardemo
