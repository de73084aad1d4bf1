// The quadrilateral SAT's vector kernel (sat_quads_vector_kernels.hpp) built with
// -mavx2 -mfma -mavx512f -mavx512vl (lab/CMakeLists.txt): the same operations as the AVX2 build,
// with thirty-two vector registers. Called only on geometry/batch_path's kAvx512 path.

#if defined(CARDEMO_BATCH_AVX512)
#if !defined(__AVX512VL__)
#error "sat_quads_avx512.cpp needs -mavx2 -mfma -mavx512f -mavx512vl (set in lab/CMakeLists.txt)"
#endif

#include "lab/geometry/sat_quads_vector_kernels.hpp"

namespace cardemo::sat_detail {

bool widestAxisOfQuadsAvx512(const double* a, const double* b, WidestAxis& out) {
  return widestAxisOfQuadsVector(a, b, out);
}

}  // namespace cardemo::sat_detail

#endif
