#include "geometry/obb3_batch.hpp"

#include <cassert>

#include "geometry/batch_path.hpp"

namespace cardemo {

Obb3Batch::Obb3Batch(std::span<const Obb3> boxes) {
  for (auto* group : {&center_, &half_}) {
    for (std::vector<double>& v : *group) v.reserve(boxes.size());
  }
  for (std::vector<double>& v : rotation_) v.reserve(boxes.size());
  for (const Obb3& b : boxes) {
    for (int k = 0; k < 3; ++k) {
      center_[static_cast<std::size_t>(k)].push_back(b.center[k]);
      half_[static_cast<std::size_t>(k)].push_back(b.half[k]);
      for (int j = 0; j < 3; ++j) {
        rotation_[static_cast<std::size_t>(3 * j + k)].push_back(b.rotation(k, j));
      }
    }
  }
}

Obb3 Obb3Batch::box(std::size_t i) const {
  assert(i < size());
  Obb3 b;
  for (int k = 0; k < 3; ++k) {
    b.center[k] = center_[static_cast<std::size_t>(k)][i];
    b.half[k] = half_[static_cast<std::size_t>(k)][i];
    for (int j = 0; j < 3; ++j)
      b.rotation(k, j) = rotation_[static_cast<std::size_t>(3 * j + k)][i];
  }
  return b;
}

std::size_t Obb3Batch::memoryBytes() const {
  std::size_t doubles = 0;
  for (const auto& v : center_) doubles += v.capacity();
  for (const auto& v : rotation_) doubles += v.capacity();
  for (const auto& v : half_) doubles += v.capacity();
  return doubles * sizeof(double);
}

batch_detail::Box3Arrays Obb3Batch::arrays() const {
  batch_detail::Box3Arrays a{};
  a.cx = center_[0].data();
  a.cy = center_[1].data();
  a.cz = center_[2].data();
  for (std::size_t m = 0; m < 9; ++m) a.r[m] = rotation_[m].data();
  a.hx = half_[0].data();
  a.hy = half_[1].data();
  a.hz = half_[2].data();
  return a;
}

namespace {

batch_detail::Box3One unpack(const Obb3& a) {
  batch_detail::Box3One one{};
  one.cx = a.center.x();
  one.cy = a.center.y();
  one.cz = a.center.z();
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) one.r[3 * j + k] = a.rotation(k, j);
  }
  one.hx = a.half.x();
  one.hy = a.half.y();
  one.hz = a.half.z();
  return one;
}

}  // namespace

void overlapObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<std::uint8_t> hit) {
  assert(hit.size() == many.size());
  const batch_detail::Box3One one = unpack(a);
#if defined(CARDEMO_BATCH_AVX2)
  // The AVX-512 path is 2D only; its 3D kernels are the AVX2 ones.
  if (batchPath() != BatchPath::kPortable) {
    batch_detail::overlap3Avx2(one, many.arrays(), 0, many.size(), hit.data());
    return;
  }
#endif
  batch_detail::overlap3Portable(one, many.arrays(), 0, many.size(), hit.data());
}

void separationObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<double> separation) {
  assert(separation.size() == many.size());
  const batch_detail::Box3One one = unpack(a);
#if defined(CARDEMO_BATCH_AVX2)
  // The AVX-512 path is 2D only; its 3D kernels are the AVX2 ones.
  if (batchPath() != BatchPath::kPortable) {
    batch_detail::separation3Avx2(one, many.arrays(), 0, many.size(), separation.data());
    return;
  }
#endif
  batch_detail::separation3Portable(one, many.arrays(), 0, many.size(), separation.data());
}

}  // namespace cardemo
