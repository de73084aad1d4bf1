#include "lab/kernels/manifold2_batch.hpp"

#include <cassert>

#include "geometry/batch_path.hpp"

namespace cardemo {

void Manifold2Batch::resize(std::size_t n) {
  for (auto* v : {&nx_, &ny_, &p0x_, &p0y_, &p1x_, &p1y_, &separation0_, &separation1_}) {
    v->resize(n);
  }
  for (auto* v : {&feature0_, &feature1_, &count_, &reference_face_}) v->resize(n);
}

Manifold2 Manifold2Batch::manifold(std::size_t i) const {
  assert(i < size());
  Manifold2 m;
  m.count = count_[i];
  m.normal = {nx_[i], ny_[i]};
  m.reference_face = reference_face_[i];
  if (m.count > 0) m.points[0] = {{p0x_[i], p0y_[i]}, separation0_[i], feature0_[i]};
  if (m.count > 1) m.points[1] = {{p1x_[i], p1y_[i]}, separation1_[i], feature1_[i]};
  return m;
}

batch_detail::Manifold2Out Manifold2Batch::arrays() {
  return {nx_.data(),       ny_.data(),       p0x_.data(),         p0y_.data(),
          p1x_.data(),      p1y_.data(),      separation0_.data(), separation1_.data(),
          feature0_.data(), feature1_.data(), count_.data(),       reference_face_.data()};
}

void manifoldObb2Batch(const Obb2Batch& a, const Obb2Batch& b, Manifold2Batch& out,
                       const ManifoldSettings& settings) {
  assert(a.size() == b.size());
  const std::size_t n = a.size();
  out.resize(n);
  const batch_detail::Manifold2Out arrays = out.arrays();
  std::size_t done = 0;
#if defined(CARDEMO_BATCH_AVX2)
  const batch_detail::ManifoldParams params{
      settings.max_separation, 1.0 - settings.relative_tolerance, settings.absolute_tolerance};
#if defined(CARDEMO_BATCH_AVX512)
  if (batchPath() == BatchPath::kAvx512) {
    done = n / 8 * 8;
    batch_detail::manifold2Avx512(a.arrays(), b.arrays(), params, 0, done, arrays);
  }
#endif
  if (batchPath() != BatchPath::kPortable) {
    // The groups of four left (all of them on AVX2, at most one after the AVX-512 groups).
    const std::size_t start = done;
    done = n / 4 * 4;
    batch_detail::manifold2Avx2(a.arrays(), b.arrays(), params, start, done, arrays);
  }
#endif
  for (std::size_t i = done; i < n; ++i) {
    const Manifold2 m = manifoldObb2(a.box(i), b.box(i), settings);
    arrays.nx[i] = m.normal.x();
    arrays.ny[i] = m.normal.y();
    arrays.count[i] = m.count;
    arrays.reference_face[i] = m.reference_face;
    const ContactPoint2& q0 = m.points[0];
    const ContactPoint2& q1 = m.points[1];
    arrays.p0x[i] = q0.point.x();
    arrays.p0y[i] = q0.point.y();
    arrays.separation0[i] = q0.separation;
    arrays.feature0[i] = q0.feature;
    arrays.p1x[i] = q1.point.x();
    arrays.p1y[i] = q1.point.y();
    arrays.separation1[i] = q1.separation;
    arrays.feature1[i] = q1.feature;
  }
}

}  // namespace cardemo
