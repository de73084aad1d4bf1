#include "lab/kernels/obb2_batch.hpp"

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

// The pre-filter's decision margin (batch2_filter.hpp): 2^-18 H + 2^-22 (|xA| + |yA| + max |xB| +
// |yB|) + 2^-100, split into a share per box (its half extents) and a share per query (the rest).
// The factor 1 + 2^-30 covers the double roundings of these sums, roundUp the conversion.
float boxMargin(double hx, double hy) {
  return roundUp(0x1p-18 * (hx + hy) * (1.0 + 0x1p-30));
}

batch_detail::Box2One unpack(const Obb2& a) {
  return {a.center.x(), a.center.y(), a.axis.x(), a.axis.y(), a.half.x(), a.half.y()};
}

#if defined(CARDEMO_BATCH_AVX2)
float queryMargin(double hx, double hy, double center_reach, double batch_reach) {
  return roundUp((0x1p-18 * (hx + hy) + 0x1p-22 * (center_reach + batch_reach) + 0x1p-100) *
                 (1.0 + 0x1p-30));
}

// A's float copy for the pre-filter, or false when A is outside the filter's range.
bool unpackFilter(const Obb2& a, const Obb2Batch& many, batch_detail::Box2FilterOne& out) {
  const Eigen::Vector2d d = a.center - many.filterReference();
  if (!(inFilterRange(d.x()) && inFilterRange(d.y()) && inFilterRange(a.half.x()) &&
        inFilterRange(a.half.y()))) {
    return false;
  }
  out.x = static_cast<float>(d.x());
  out.y = static_cast<float>(d.y());
  out.ux = static_cast<float>(a.axis.x());
  out.uy = static_cast<float>(a.axis.y());
  out.hx = static_cast<float>(a.half.x());
  out.hy = static_cast<float>(a.half.y());
  const double reach = std::abs(static_cast<double>(out.x)) + std::abs(static_cast<double>(out.y));
  out.bound = queryMargin(a.half.x(), a.half.y(), reach, many.filterReach());
  return true;
}
#endif

}  // namespace

Obb2Batch::Obb2Batch(std::span<const Obb2> boxes) {
  for (auto* v : {&cx_, &cy_, &ux_, &uy_, &hx_, &hy_}) v->reserve(boxes.size());
  for (const Obb2& b : boxes) {
    cx_.push_back(b.center.x());
    cy_.push_back(b.center.y());
    ux_.push_back(b.axis.x());
    uy_.push_back(b.axis.y());
    hx_.push_back(b.half.x());
    hy_.push_back(b.half.y());
  }
  if (boxes.empty()) return;

  reference_ = batch_detail::filterReferenceOf(boxes);
  filter_usable_ = true;
  const std::size_t padded = (boxes.size() + kFilterGroup - 1) / kFilterGroup * kFilterGroup;
  for (auto* v : {&fx_, &fy_, &fux_, &fuy_, &fhx_, &fhy_, &fbound_}) v->reserve(padded);
  for (std::size_t i = 0; i < padded; ++i) {
    const Obb2& b = boxes[std::min(i, boxes.size() - 1)];
    const Eigen::Vector2d d = b.center - reference_;
    filter_usable_ = filter_usable_ && inFilterRange(d.x()) && inFilterRange(d.y()) &&
                     inFilterRange(b.half.x()) && inFilterRange(b.half.y());
    if (!filter_usable_) break;
    fx_.push_back(static_cast<float>(d.x()));
    fy_.push_back(static_cast<float>(d.y()));
    fux_.push_back(static_cast<float>(b.axis.x()));
    fuy_.push_back(static_cast<float>(b.axis.y()));
    fhx_.push_back(static_cast<float>(b.half.x()));
    fhy_.push_back(static_cast<float>(b.half.y()));
    fbound_.push_back(boxMargin(b.half.x(), b.half.y()));
    reach_ = std::max(reach_, std::abs(static_cast<double>(fx_.back())) +
                                  std::abs(static_cast<double>(fy_.back())));
  }
  if (!filter_usable_) {
    for (auto* v : {&fx_, &fy_, &fux_, &fuy_, &fhx_, &fhy_, &fbound_}) {
      v->clear();
      v->shrink_to_fit();
    }
  }
}

Obb2 Obb2Batch::box(std::size_t i) const {
  assert(i < size());
  return {{cx_[i], cy_[i]}, {ux_[i], uy_[i]}, {hx_[i], hy_[i]}};
}

std::size_t Obb2Batch::memoryBytes() const {
  return (cx_.capacity() + cy_.capacity() + ux_.capacity() + uy_.capacity() + hx_.capacity() +
          hy_.capacity()) *
             sizeof(double) +
         (fx_.capacity() + fy_.capacity() + fux_.capacity() + fuy_.capacity() + fhx_.capacity() +
          fhy_.capacity() + fbound_.capacity()) *
             sizeof(float);
}

batch_detail::Box2Arrays Obb2Batch::arrays() const {
  return {cx_.data(), cy_.data(), ux_.data(), uy_.data(), hx_.data(), hy_.data()};
}

batch_detail::Box2FilterArrays Obb2Batch::filterArrays() const {
  return {fx_.data(),  fy_.data(),  fux_.data(),   fuy_.data(),
          fhx_.data(), fhy_.data(), fbound_.data()};
}

std::size_t overlapObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<std::uint8_t> hit) {
  assert(hit.size() == many.size());
  const batch_detail::Box2One one = unpack(a);
  const std::size_t n = many.size();
#if defined(CARDEMO_BATCH_AVX2)
  const BatchPath path = batchPath();
  if (path != BatchPath::kPortable) {
    batch_detail::Box2FilterOne fa{};
    const bool filtered = many.filterUsable() && unpackFilter(a, many, fa);
#if defined(CARDEMO_BATCH_AVX512)
    if (path == BatchPath::kAvx512) {
      if (filtered) {
        return batch_detail::overlap2FilteredAvx512(one, many.arrays(), fa, many.filterArrays(), 0,
                                                    n, hit.data());
      }
      batch_detail::overlap2Avx512(one, many.arrays(), 0, n, hit.data());
      return n;
    }
#endif
    if (filtered) {
      return batch_detail::overlap2FilteredAvx2(one, many.arrays(), fa, many.filterArrays(), 0, n,
                                                hit.data());
    }
    batch_detail::overlap2Avx2(one, many.arrays(), 0, n, hit.data());
    return n;
  }
#endif
  batch_detail::overlap2Portable(one, many.arrays(), 0, n, hit.data());
  return 0;
}

void collideObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<double> separation,
                      std::span<double> normal_x, std::span<double> normal_y) {
  assert(separation.size() == many.size() && normal_x.size() == many.size() &&
         normal_y.size() == many.size());
  const batch_detail::Box2One one = unpack(a);
  const batch_detail::Sat2Out out{separation.data(), normal_x.data(), normal_y.data()};
#if defined(CARDEMO_BATCH_AVX512)
  if (batchPath() == BatchPath::kAvx512) {
    batch_detail::collide2Avx512(one, many.arrays(), 0, many.size(), out);
    return;
  }
#endif
#if defined(CARDEMO_BATCH_AVX2)
  // Also on kAvx512 when the lab is built without its AVX-512 kernels.
  if (batchPath() != BatchPath::kPortable) {
    batch_detail::collide2Avx2(one, many.arrays(), 0, many.size(), out);
    return;
  }
#endif
  batch_detail::collide2Portable(one, many.arrays(), 0, many.size(), out);
}

}  // namespace cardemo
