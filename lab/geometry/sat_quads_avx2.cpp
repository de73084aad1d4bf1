// The quadrilateral SAT's vector kernel (sat_quads_vector_kernels.hpp) built with
// -mavx2 -mfma (lab/CMakeLists.txt), called only after geometry/batch_path says the CPU has AVX2.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__)
#error "sat_quads_avx2.cpp needs -mavx2 -mfma (set in lab/CMakeLists.txt)"
#endif

#include "lab/geometry/sat_quads_vector_kernels.hpp"

namespace cardemo::sat_detail {

bool widestAxisOfQuadsAvx2(const double* a, const double* b, WidestAxis& out) {
  return widestAxisOfQuadsVector(a, b, out);
}

}  // namespace cardemo::sat_detail

#endif
