#include "kernels/obb3_batch.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/batch_path.hpp"

namespace cardemo {
Obb3Batch::Obb3Batch(std::span<const Obb3> boxes) {
  for (auto* group : {&center_, &half_}) {
    for (std::vector<double>& v : *group) v.reserve(boxes.size());
  }
  for (std::vector<double>& v : rotation_) v.reserve(boxes.size());
  for (const Obb3& b : boxes) {
    frame_defect_ = std::max(frame_defect_, b.frameDefect());
    for (int k = 0; k < 3; ++k) {
      center_[static_cast<std::size_t>(k)].push_back(b.center[k]);
      half_[static_cast<std::size_t>(k)].push_back(b.half[k]);
      for (int j = 0; j < 3; ++j) {
        rotation_[3 * static_cast<std::size_t>(j) + static_cast<std::size_t>(k)].push_back(
            b.rotation()(k, j));
      }
    }
  }
}

Obb3 Obb3Batch::box(std::size_t i) const {
  assert(i < size());
  Obb3 b;
  Eigen::Matrix3d rotation;
  for (int k = 0; k < 3; ++k) {
    b.center[k] = center_[static_cast<std::size_t>(k)][i];
    b.half[k] = half_[static_cast<std::size_t>(k)][i];
    for (int j = 0; j < 3; ++j)
      rotation(k, j) = rotation_[3 * static_cast<std::size_t>(j) + static_cast<std::size_t>(k)][i];
  }
  b.setRotation(rotation);
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

// Coefficients of the kernels' A-frame filter for this A against `many` (batch_kernels.hpp). With
// U = 2^-53 and phi the larger frame defect, an A-frame edge gap (gap times axis length) is within
// (16U + 2 phi) of the pair's scale S of the gap on the exact cross product of the stored columns,
// and the accurate kernel within 10U S of that: 32U + 6 phi covers both with room to spare
// (measured: under 16U S for phi up to 20U). A normalised gap is within (22U + 3 phi) S / |axis|;
// (64U + 8 phi) / |axis| <= 2^-40 sets the floor on the squared axis length.
void setFilter(const Obb3& a, const Obb3Batch& many, batch_detail::Box3One& one) {
  constexpr double kU = 0x1p-53;
  const double phi = std::max(a.frameDefect(), many.frameDefect());
  if (!(phi <= 0x1p-30)) {
    one.edge_gap_error = std::numeric_limits<double>::infinity();
    one.min_edge_length2 = std::numeric_limits<double>::infinity();
    return;
  }
  one.edge_gap_error = 32.0 * kU + 6.0 * phi;
  const double root = (64.0 * kU + 8.0 * phi) / 0x1p-40;
  one.min_edge_length2 = root * root;
}

batch_detail::Box3One unpack(const Obb3& a) {
  batch_detail::Box3One one{};
  one.cx = a.center.x();
  one.cy = a.center.y();
  one.cz = a.center.z();
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) one.r[3 * j + k] = a.rotation()(k, j);
  }
  one.hx = a.half.x();
  one.hy = a.half.y();
  one.hz = a.half.z();
  return one;
}

}  // namespace

void overlapObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<std::uint8_t> hit) {
  assert(hit.size() == many.size());
  batch_detail::Box3One one = unpack(a);
  setFilter(a, many, one);
#if defined(CARDEMO_BATCH_AVX512)
  if (batchPath() == BatchPath::kAvx512) {
    batch_detail::overlap3Avx512(one, many.arrays(), 0, many.size(), hit.data());
    return;
  }
#endif
#if defined(CARDEMO_BATCH_AVX2)
  if (batchPath() != BatchPath::kPortable) {
    batch_detail::overlap3Avx2(one, many.arrays(), 0, many.size(), hit.data());
    return;
  }
#endif
  batch_detail::overlap3Portable(one, many.arrays(), 0, many.size(), hit.data());
}

void separationObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<double> separation) {
  assert(separation.size() == many.size());
  batch_detail::Box3One one = unpack(a);
  setFilter(a, many, one);
#if defined(CARDEMO_BATCH_AVX512)
  if (batchPath() == BatchPath::kAvx512) {
    batch_detail::separation3Avx512(one, many.arrays(), 0, many.size(), separation.data());
    return;
  }
#endif
#if defined(CARDEMO_BATCH_AVX2)
  if (batchPath() != BatchPath::kPortable) {
    batch_detail::separation3Avx2(one, many.arrays(), 0, many.size(), separation.data());
    return;
  }
#endif
  batch_detail::separation3Portable(one, many.arrays(), 0, many.size(), separation.data());
}

}  // namespace cardemo
