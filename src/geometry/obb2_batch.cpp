#include "geometry/obb2_batch.hpp"

#include <cassert>

#include "geometry/batch_path.hpp"

namespace cardemo {

Obb2Batch::Obb2Batch(std::span<const Obb2> boxes) {
  for (std::vector<double>* v : {&cx_, &cy_, &ux_, &uy_, &hx_, &hy_}) v->reserve(boxes.size());
  for (const Obb2& b : boxes) {
    cx_.push_back(b.center.x());
    cy_.push_back(b.center.y());
    ux_.push_back(b.axis.x());
    uy_.push_back(b.axis.y());
    hx_.push_back(b.half.x());
    hy_.push_back(b.half.y());
  }
}

Obb2 Obb2Batch::box(std::size_t i) const {
  assert(i < size());
  return {{cx_[i], cy_[i]}, {ux_[i], uy_[i]}, {hx_[i], hy_[i]}};
}

std::size_t Obb2Batch::memoryBytes() const {
  return (cx_.capacity() + cy_.capacity() + ux_.capacity() + uy_.capacity() + hx_.capacity() +
          hy_.capacity()) *
         sizeof(double);
}

batch_detail::Box2Arrays Obb2Batch::arrays() const {
  return {cx_.data(), cy_.data(), ux_.data(), uy_.data(), hx_.data(), hy_.data()};
}

namespace {

batch_detail::Box2One unpack(const Obb2& a) {
  return {a.center.x(), a.center.y(), a.axis.x(), a.axis.y(), a.half.x(), a.half.y()};
}

}  // namespace

void overlapObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<std::uint8_t> hit) {
  assert(hit.size() == many.size());
  const batch_detail::Box2One one = unpack(a);
#if defined(CARDEMO_BATCH_AVX2)
  if (batchPath() == BatchPath::kAvx2) {
    batch_detail::overlap2Avx2(one, many.arrays(), 0, many.size(), hit.data());
    return;
  }
#endif
  batch_detail::overlap2Portable(one, many.arrays(), 0, many.size(), hit.data());
}

void collideObb2Batch(const Obb2& a, const Obb2Batch& many, std::span<double> separation,
                      std::span<double> normal_x, std::span<double> normal_y) {
  assert(separation.size() == many.size() && normal_x.size() == many.size() &&
         normal_y.size() == many.size());
  const batch_detail::Box2One one = unpack(a);
  const batch_detail::Sat2Out out{separation.data(), normal_x.data(), normal_y.data()};
#if defined(CARDEMO_BATCH_AVX2)
  if (batchPath() == BatchPath::kAvx2) {
    batch_detail::collide2Avx2(one, many.arrays(), 0, many.size(), out);
    return;
  }
#endif
  batch_detail::collide2Portable(one, many.arrays(), 0, many.size(), out);
}

}  // namespace cardemo
