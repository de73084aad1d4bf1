// overlapObb3's and collideObb3's vector kernels (obb3_vector_kernels.hpp) built with
// -mavx2 -mfma -mavx512f -mavx512vl (lab/CMakeLists.txt): the same operations as the AVX2 build,
// with thirty-two vector registers. Called only on geometry/batch_path's kAvx512 path.

#if defined(CARDEMO_BATCH_AVX512)
#if !defined(__AVX512VL__)
#error "obb3_avx512.cpp needs -mavx2 -mfma -mavx512f -mavx512vl (set in lab/CMakeLists.txt)"
#endif

#include "lab/geometry/obb3_vector_kernels.hpp"

namespace cardemo::obb3_detail {

Verdict overlapAvx512(const double* a, const double* b, double phi) {
  return overlapVector(a, b, phi);
}

bool largestGapAvx512(const double* a, const double* b, double phi, LargestGap& out) {
  return largestGapVector(a, b, phi, out);
}

}  // namespace cardemo::obb3_detail

#endif
