#pragma once
/// Internal to the batch kernels: what the 2D and 3D batches share when they build the float copy
/// that their pre-filters read (batch2_filter.hpp, batch3_filter.hpp).

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace cardemo::batch_detail {

/// The float pre-filters' range: centres within 2^60 m of the batch's reference point and half
/// extents up to 2^60 m keep every float operation far from overflow.
inline constexpr double kFilterRange = 0x1p60;
/// The float copies are padded to whole lane groups of the widest float path (AVX-512F: sixteen).
inline constexpr std::size_t kFilterGroup = 16;

/// True when |x| is within kFilterRange (false for NaN).
inline bool inFilterRange(double x) {
  return std::abs(x) <= kFilterRange;
}

/// The smallest float >= x (x finite, within float range).
inline float roundUp(double x) {
  float r = static_cast<float>(x);
  if (static_cast<double>(r) < x) r = std::nextafter(r, std::numeric_limits<float>::infinity());
  return r;
}

/// The point a batch's float centres are taken relative to: the middle of the centres' bounds, so
/// that the rounding to float is relative to the batch's spread, not to the distance from the
/// origin (the difference is taken in double). `boxes` is not empty; Box has an Eigen `center`.
template <class Box>
auto filterReferenceOf(std::span<const Box> boxes) {
  auto lo = boxes[0].center, hi = boxes[0].center;
  for (const Box& b : boxes) {
    lo = lo.cwiseMin(b.center);
    hi = hi.cwiseMax(b.center);
  }
  return decltype(lo)(0.5 * lo + 0.5 * hi);
}

}  // namespace cardemo::batch_detail
