#include "lab/kernels/obb3_batch.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/batch_path.hpp"
#include "lab/kernels/filter_copy.hpp"

namespace cardemo {
namespace {

using batch_detail::inFilterRange;
using batch_detail::kFilterGroup;
using batch_detail::roundUp;

// One box's share of the float pre-filter's margin (batch3_filter.hpp): 2^-17 times its half
// extents' sum, plus 2^-21 times |x|_1 of its float centre, plus `floor`. The factor 1 + 2^-30
// covers the double roundings of these sums, roundUp the conversion.
float filterShare(double half_sum, double reach, double floor) {
  return roundUp((0x1p-17 * half_sum + 0x1p-21 * reach + floor) * (1.0 + 0x1p-30));
}

}  // namespace

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
  if (boxes.empty()) return;

  reference_ = batch_detail::filterReferenceOf(boxes);
  filter_usable_ = true;
  const std::size_t padded = (boxes.size() + kFilterGroup - 1) / kFilterGroup * kFilterGroup;
  for (std::size_t i = 0; i < padded && filter_usable_; ++i) {
    const Obb3& b = boxes[std::min(i, boxes.size() - 1)];
    const Eigen::Vector3d d = b.center - reference_;
    double reach = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const int e = static_cast<int>(k);
      filter_usable_ = filter_usable_ && inFilterRange(d[e]) && inFilterRange(b.half[e]);
      filter_center_[k].push_back(static_cast<float>(d[e]));
      filter_half_[k].push_back(static_cast<float>(b.half[e]));
      reach += std::abs(static_cast<double>(filter_center_[k].back()));
      for (std::size_t j = 0; j < 3; ++j) {
        filter_rotation_[3 * j + k].push_back(
            static_cast<float>(b.rotation()(e, static_cast<int>(j))));
      }
    }
    filter_bound_.push_back(filterShare(b.half.sum(), reach, 0.0));
  }
  if (!filter_usable_) {
    for (auto* group : {&filter_center_, &filter_half_}) {
      for (Aligned<float>& v : *group) Aligned<float>().swap(v);
    }
    for (Aligned<float>& v : filter_rotation_) Aligned<float>().swap(v);
    Aligned<float>().swap(filter_bound_);
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
  std::size_t floats = filter_bound_.capacity();
  for (const auto& v : filter_center_) floats += v.capacity();
  for (const auto& v : filter_rotation_) floats += v.capacity();
  for (const auto& v : filter_half_) floats += v.capacity();
  return doubles * sizeof(double) + floats * sizeof(float);
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

batch_detail::Box3FilterArrays Obb3Batch::filterArrays() const {
  batch_detail::Box3FilterArrays a{};
  for (std::size_t k = 0; k < 3; ++k) {
    a.c[k] = filter_center_[k].data();
    a.h[k] = filter_half_[k].data();
  }
  for (std::size_t m = 0; m < 9; ++m) a.r[m] = filter_rotation_[m].data();
  a.bound = filter_bound_.data();
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

#if defined(CARDEMO_BATCH_AVX2)
// A's float copy for the pre-filter, or false when A or the batch is outside the filter's range,
// or the frames are too far from orthonormal for the A-frame gaps (setFilter turned that off).
bool unpackFilter(const Obb3& a, const Obb3Batch& many, const batch_detail::Box3One& one,
                  batch_detail::Box3FilterOne& out) {
  if (!many.filterUsable() || !(one.edge_gap_error < 1.0)) return false;
  const Eigen::Vector3d d = a.center - many.filterReference();
  double reach = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (!(inFilterRange(d[k]) && inFilterRange(a.half[k]))) return false;
    out.c[k] = static_cast<float>(d[k]);
    out.h[k] = static_cast<float>(a.half[k]);
    reach += std::abs(static_cast<double>(out.c[k]));
  }
  for (std::size_t m = 0; m < 9; ++m) out.r[m] = static_cast<float>(one.r[m]);
  out.bound = filterShare(a.half.sum(), reach, 0x1p-100);
  return true;
}
#endif

}  // namespace

std::size_t overlapObb3Batch(const Obb3& a, const Obb3Batch& many, std::span<std::uint8_t> hit) {
  assert(hit.size() == many.size());
  batch_detail::Box3One one = unpack(a);
  setFilter(a, many, one);
  const std::size_t n = many.size();
#if defined(CARDEMO_BATCH_AVX2)
  const BatchPath path = batchPath();
  if (path != BatchPath::kPortable) {
    // The float pre-filter: sixteen floats a step on AVX-512, eight on AVX2; the boxes it leaves
    // undecided go to the double kernel of the same path.
    batch_detail::Box3FilterOne fa{};
    if (unpackFilter(a, many, one, fa)) {
#if defined(CARDEMO_BATCH_AVX512)
      if (path == BatchPath::kAvx512) {
        return batch_detail::overlap3FilteredAvx512(one, many.arrays(), fa, many.filterArrays(), 0,
                                                    n, hit.data());
      }
#endif
      return batch_detail::overlap3FilteredAvx2(one, many.arrays(), fa, many.filterArrays(), 0, n,
                                                hit.data());
    }
#if defined(CARDEMO_BATCH_AVX512)
    if (path == BatchPath::kAvx512) {
      batch_detail::overlap3Avx512(one, many.arrays(), 0, n, hit.data());
      return n;
    }
#endif
    batch_detail::overlap3Avx2(one, many.arrays(), 0, n, hit.data());
    return n;
  }
#endif
  batch_detail::overlap3Portable(one, many.arrays(), 0, n, hit.data());
  return 0;
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
