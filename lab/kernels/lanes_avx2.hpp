#pragma once
/// Internal to the files built for AVX2 (batch_avx2.cpp, filter_avx2.cpp and lab/geometry's vector
/// kernels): the AVX2 lanes, four doubles (Lane4, with its mask) for the double kernels and eight
/// floats (Float8) for the pre-filters, and the register helpers the one-pair kernels share.
//
// Nothing but the intrinsics, and internal linkage: every file that includes this one is built
// with -mavx2 -mfma or more, and none of its copies can be picked by the linker for another
// (batch_avx2.cpp says why that matters).

#include <immintrin.h>

#include <cstddef>
#include <cstdint>

namespace cardemo::batch_detail {
namespace {

// ----- four doubles: the double kernels of batch_kernels.hpp

struct Mask4 {
  __m256d m;  // all ones or all zeros per lane
};

struct Lane4 {
  static constexpr std::size_t kWidth = 4;
  using Mask = Mask4;
  __m256d v;
  static Lane4 load(const double* p) { return {_mm256_loadu_pd(p)}; }
  static Lane4 splat(double x) { return {_mm256_set1_pd(x)}; }
};

[[gnu::always_inline]] inline Lane4 operator+(Lane4 a, Lane4 b) {
  return {_mm256_add_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Lane4 operator-(Lane4 a, Lane4 b) {
  return {_mm256_sub_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Lane4 operator*(Lane4 a, Lane4 b) {
  return {_mm256_mul_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Lane4 operator/(Lane4 a, Lane4 b) {
  return {_mm256_div_pd(a.v, b.v)};
}
// Flipping the sign bit is exactly what scalar negation does, zeros and NaNs included.
[[gnu::always_inline]] inline Lane4 operator-(Lane4 a) {
  return {_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))};
}
[[gnu::always_inline]] inline Lane4 abs(Lane4 a) {
  return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)};
}
[[gnu::always_inline]] inline Lane4 sqrt(Lane4 a) {
  return {_mm256_sqrt_pd(a.v)};
}
[[gnu::always_inline]] inline Lane4 fma(Lane4 a, Lane4 b, Lane4 c) {
  return {_mm256_fmadd_pd(a.v, b.v, c.v)};
}
// Ordered, non-signalling: false for NaN, as the scalar operators.
[[gnu::always_inline]] inline Mask4 gt(Lane4 a, Lane4 b) {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)};
}
[[gnu::always_inline]] inline Mask4 lt(Lane4 a, Lane4 b) {
  return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline Mask4 operator|(Mask4 a, Mask4 b) {
  return {_mm256_or_pd(a.m, b.m)};
}
[[gnu::always_inline]] inline Mask4 operator&(Mask4 a, Mask4 b) {
  return {_mm256_and_pd(a.m, b.m)};
}
[[gnu::always_inline]] inline Lane4 select(Mask4 m, Lane4 a, Lane4 b) {
  return {_mm256_blendv_pd(b.v, a.v, m.m)};
}
[[gnu::always_inline]] inline void store(double* p, Lane4 a) {
  _mm256_storeu_pd(p, a.v);
}
[[gnu::always_inline]] inline void storeHits(std::uint8_t* p, Mask4 separated) {
  // Spread the four sign bits into the low bit of four bytes (bit k to byte k: one multiply),
  // flip them (hit = not separated) and store the four bytes at once.
  const auto bits = static_cast<std::uint32_t>(_mm256_movemask_pd(separated.m));
  const std::uint32_t bytes = ((bits * 0x00204081u) & 0x01010101u) ^ 0x01010101u;
  __builtin_memcpy(p, &bytes, sizeof bytes);
}
// The manifold kernel's mask and sign-bit operations (manifold2_lanes.hpp): bitwise logic.
[[gnu::always_inline]] inline Mask4 operator^(Mask4 a, Mask4 b) {
  return {_mm256_xor_pd(a.m, b.m)};
}
[[gnu::always_inline]] inline Mask4 andNot(Mask4 a, Mask4 b) {
  return {_mm256_andnot_pd(a.m, b.m)};
}
[[gnu::always_inline]] inline Lane4 onlyWhere(Mask4 m, Lane4 x) {
  return {_mm256_and_pd(m.m, x.v)};
}
[[gnu::always_inline]] inline Lane4 onlyWhereNot(Mask4 m, Lane4 x) {
  return {_mm256_andnot_pd(m.m, x.v)};
}
[[gnu::always_inline]] inline Lane4 flipSign(Lane4 x, Lane4 sign_bits) {
  return {_mm256_xor_pd(x.v, sign_bits.v)};
}
// batch_kernels.hpp's masked sign flip, without a blend.
[[gnu::always_inline]] inline Lane4 negateWhere(Mask4 m, Lane4 x) {
  return {_mm256_xor_pd(x.v, _mm256_and_pd(m.m, _mm256_set1_pd(-0.0)))};
}
// The lanes hold small whole numbers: converted exactly, four 32-bit integers stored at once.
[[gnu::always_inline]] inline void storeInt32(std::int32_t* p, Lane4 a) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm256_cvtpd_epi32(a.v));
}
[[gnu::always_inline]] inline bool allOf(Mask4 m) {
  return _mm256_movemask_pd(m.m) == 0xF;
}
[[gnu::always_inline]] inline unsigned laneBits(Mask4 m) {
  return static_cast<unsigned>(_mm256_movemask_pd(m.m));
}

// ----- eight floats: the pre-filters (batch2_filter.hpp, batch3_filter.hpp)

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

// ----- raw registers: the one-pair kernels (lab/geometry/*_vector_kernels.hpp)

// The largest of the four lanes.
[[gnu::always_inline]] inline double largestLane(__m256d v) {
  const __m128d half = _mm_max_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_max_pd(half, _mm_unpackhi_pd(half, half)));
}

}  // namespace
}  // namespace cardemo::batch_detail
