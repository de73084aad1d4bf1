// The 2D boolean batch SAT with the float pre-filter, eight pairs per AVX2 instruction; undecided
// lane groups go to the AVX2 double kernel (batch_avx2.cpp). Built with -mavx2 -mfma
// (CMakeLists.txt) and called only after batchPathAvailable says the CPU has both.
//
// Includes nothing but the intrinsics and the kernel header, for the reason given in
// batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "batch2_avx2.cpp needs -mavx2 -mfma (set in CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "kernels/batch2_filter.hpp"

namespace cardemo::batch_detail {
namespace {

struct Float8 {
  static constexpr std::size_t kWidth = 8;
  __m256 v;
  static Float8 load(const float* p) { return {_mm256_loadu_ps(p)}; }
  static Float8 splat(float x) { return {_mm256_set1_ps(x)}; }
};

[[gnu::always_inline]] inline Float8 operator+(Float8 a, Float8 b) {
  return {_mm256_add_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float8 operator-(Float8 a, Float8 b) {
  return {_mm256_sub_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float8 operator*(Float8 a, Float8 b) {
  return {_mm256_mul_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float8 fmadd(Float8 a, Float8 b, Float8 c) {
  return {_mm256_fmadd_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float8 fmsub(Float8 a, Float8 b, Float8 c) {
  return {_mm256_fmsub_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float8 fnmadd(Float8 a, Float8 b, Float8 c) {
  return {_mm256_fnmadd_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float8 abs(Float8 a) {
  return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)};
}
[[gnu::always_inline]] inline Float8 max(Float8 a, Float8 b) {
  return {_mm256_max_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline unsigned gtBits(Float8 a, Float8 b) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)));
}

}  // namespace

std::size_t overlap2FilteredAvx2(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                 const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                 std::uint8_t* hit) {
  return runFilteredOverlap2<Float8>(fa, fb, first, last, hit, [&](std::size_t i0, std::size_t i1) {
    overlap2Avx2(a, b, i0, i1, hit);
  });
}

}  // namespace cardemo::batch_detail

#endif
