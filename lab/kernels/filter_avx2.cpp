// The 2D and 3D boolean batch SATs with their float pre-filters, eight pairs per AVX2 instruction;
// the pairs they leave undecided go to the AVX2 double kernels (batch_avx2.cpp): with their lane
// group in 2D, one by one in 3D (filter_run.hpp). Built with -mavx2 -mfma
// (lab/CMakeLists.txt) and called only after batchPathAvailable says the CPU has both.
//
// Includes nothing but the intrinsics and the kernel header, for the reason given in
// batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "filter_avx2.cpp needs -mavx2 -mfma (set in lab/CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "lab/kernels/batch2_filter.hpp"
#include "lab/kernels/batch3_filter.hpp"
#include "lab/kernels/box_fields.hpp"
#include "lab/kernels/lanes_avx2.hpp"

namespace cardemo::batch_detail {

std::size_t overlap2FilteredAvx2(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                 const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                 std::uint8_t* hit) {
  return runFilteredOverlap2<Float8>(fa, fb, first, last, hit, [&](std::size_t i0, std::size_t i1) {
    overlap2Avx2(a, b, i0, i1, hit);
  });
}

std::size_t overlap3FilteredAvx2(const Box3One& a, const Box3Arrays& b, const Box3FilterOne& fa,
                                 const Box3FilterArrays& fb, std::size_t first, std::size_t last,
                                 std::uint8_t* hit) {
  return runFilteredOverlap3<Float8>(
      fa, fb, first, last, hit, [&](const std::size_t* boxes, std::size_t count) {
        decideOpenBoxes<4>(fieldsOf(b).field, boxes, count, hit,
                           [&](const double(&f)[15][4], std::uint8_t* group_hit) {
                             overlap3Avx2(a, arraysOf(f), 0, 4, group_hit);
                           });
      });
}

}  // namespace cardemo::batch_detail

#endif
