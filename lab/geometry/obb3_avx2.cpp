// overlapObb3's and collideObb3's vector kernels (obb3_vector_kernels.hpp) built with
// -mavx2 -mfma (lab/CMakeLists.txt), called only after geometry/batch_path says the CPU has AVX2.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__)
#error "obb3_avx2.cpp needs -mavx2 -mfma (set in lab/CMakeLists.txt)"
#endif

#include "lab/geometry/obb3_vector_kernels.hpp"

namespace cardemo::obb3_detail {

Verdict overlapAvx2(const double* a, const double* b, double phi) {
  return overlapVector(a, b, phi);
}

bool largestGapAvx2(const double* a, const double* b, double phi, LargestGap& out) {
  return largestGapVector(a, b, phi, out);
}

}  // namespace cardemo::obb3_detail

#endif
