#pragma once
/// Internal to batch_avx512.cpp: the AVX-512 lanes, sixteen floats (Float16) for the pre-filters
/// and eight doubles (Double8, with its mask) for the double kernels.
//
// Nothing but the intrinsics, and internal linkage (as lanes_avx2.hpp).

#include <immintrin.h>

#include <cstddef>
#include <cstdint>

namespace cardemo::batch_detail {
namespace {

// ----- sixteen floats: the pre-filter

struct Float16 {
  static constexpr std::size_t kWidth = 16;
  __m512 v;
  static Float16 load(const float* p) { return {_mm512_loadu_ps(p)}; }
  static Float16 splat(float x) { return {_mm512_set1_ps(x)}; }
};

[[gnu::always_inline]] inline Float16 operator+(Float16 a, Float16 b) {
  return {_mm512_add_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float16 operator-(Float16 a, Float16 b) {
  return {_mm512_sub_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float16 operator*(Float16 a, Float16 b) {
  return {_mm512_mul_ps(a.v, b.v)};
}
[[gnu::always_inline]] inline Float16 fmadd(Float16 a, Float16 b, Float16 c) {
  return {_mm512_fmadd_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float16 fmsub(Float16 a, Float16 b, Float16 c) {
  return {_mm512_fmsub_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float16 fnmadd(Float16 a, Float16 b, Float16 c) {
  return {_mm512_fnmadd_ps(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Float16 abs(Float16 a) {
  return {_mm512_abs_ps(a.v)};
}
// The zero-masked form with every lane on is plain vmaxps; GCC 12 warns about the uninitialised
// source operand of _mm512_max_ps (GCC bug 105593).
[[gnu::always_inline]] inline Float16 max(Float16 a, Float16 b) {
  return {_mm512_maskz_max_ps(static_cast<__mmask16>(0xFFFF), a.v, b.v)};
}
[[gnu::always_inline]] inline unsigned gtBits(Float16 a, Float16 b) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ));
}

// ----- eight doubles: the double kernels of batch_kernels.hpp

struct Mask8 {
  __mmask8 m;
};

struct Double8 {
  static constexpr std::size_t kWidth = 8;
  using Mask = Mask8;
  __m512d v;
  static Double8 load(const double* p) { return {_mm512_loadu_pd(p)}; }
  static Double8 splat(double x) { return {_mm512_set1_pd(x)}; }
};

[[gnu::always_inline]] inline Double8 operator+(Double8 a, Double8 b) {
  return {_mm512_add_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Double8 operator-(Double8 a, Double8 b) {
  return {_mm512_sub_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Double8 operator*(Double8 a, Double8 b) {
  return {_mm512_mul_pd(a.v, b.v)};
}
[[gnu::always_inline]] inline Double8 operator/(Double8 a, Double8 b) {
  return {_mm512_div_pd(a.v, b.v)};
}
// The zero-masked form with every lane on, for the same GCC bug as max above.
[[gnu::always_inline]] inline Double8 sqrt(Double8 a) {
  return {_mm512_maskz_sqrt_pd(static_cast<__mmask8>(0xFF), a.v)};
}
[[gnu::always_inline]] inline Double8 fma(Double8 a, Double8 b, Double8 c) {
  return {_mm512_fmadd_pd(a.v, b.v, c.v)};
}
// Flipping the sign bit is exactly what scalar negation does, zeros and NaNs included.
[[gnu::always_inline]] inline Double8 operator-(Double8 a) {
  return {_mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(a.v), _mm512_castpd_si512(_mm512_set1_pd(-0.0))))};
}
[[gnu::always_inline]] inline Double8 abs(Double8 a) {
  return {_mm512_abs_pd(a.v)};
}
// Ordered, non-signalling: false for NaN, as the scalar operators.
[[gnu::always_inline]] inline Mask8 gt(Double8 a, Double8 b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)};
}
[[gnu::always_inline]] inline Mask8 lt(Double8 a, Double8 b) {
  return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)};
}
[[gnu::always_inline]] inline Mask8 operator|(Mask8 a, Mask8 b) {
  return {static_cast<__mmask8>(a.m | b.m)};
}
[[gnu::always_inline]] inline Mask8 operator&(Mask8 a, Mask8 b) {
  return {static_cast<__mmask8>(a.m & b.m)};
}
[[gnu::always_inline]] inline bool allOf(Mask8 m) {
  return m.m == 0xFF;
}
[[gnu::always_inline]] inline unsigned laneBits(Mask8 m) {
  return m.m;
}
[[gnu::always_inline]] inline Double8 select(Mask8 m, Double8 a, Double8 b) {
  return {_mm512_mask_blend_pd(m.m, b.v, a.v)};
}
[[gnu::always_inline]] inline Double8 negateWhere(Mask8 m, Double8 a) {
  return {_mm512_castsi512_pd(_mm512_mask_xor_epi64(_mm512_castpd_si512(a.v), m.m,
                                                    _mm512_castpd_si512(a.v),
                                                    _mm512_castpd_si512(_mm512_set1_pd(-0.0))))};
}
[[gnu::always_inline]] inline void store(double* p, Double8 a) {
  _mm512_storeu_pd(p, a.v);
}
[[gnu::always_inline]] inline void storeHits(std::uint8_t* p, Mask8 separated) {
  const std::uint64_t bytes = hitBytes(separated.m);
  __builtin_memcpy(p, &bytes, 8);
}
// The manifold kernel's mask and sign-bit operations (manifold2_lanes.hpp): mask-register logic
// and zero-masked moves. AVX-512F has no xor on doubles (that is AVX-512DQ), so sign bits are
// flipped with the 64-bit integer xor, which does the same to the bits.
[[gnu::always_inline]] inline Mask8 operator^(Mask8 a, Mask8 b) {
  return {static_cast<__mmask8>(a.m ^ b.m)};
}
[[gnu::always_inline]] inline Mask8 andNot(Mask8 a, Mask8 b) {
  return {static_cast<__mmask8>(~a.m & b.m)};
}
[[gnu::always_inline]] inline Double8 onlyWhere(Mask8 m, Double8 x) {
  return {_mm512_maskz_mov_pd(m.m, x.v)};
}
[[gnu::always_inline]] inline Double8 onlyWhereNot(Mask8 m, Double8 x) {
  return {_mm512_maskz_mov_pd(static_cast<__mmask8>(~m.m), x.v)};
}
[[gnu::always_inline]] inline Double8 flipSign(Double8 x, Double8 sign_bits) {
  return {_mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(x.v), _mm512_castpd_si512(sign_bits.v)))};
}
// The lanes hold small whole numbers: converted exactly, eight 32-bit integers stored at once
// (zero-masked with every lane on, for the GCC bug named at max above).
[[gnu::always_inline]] inline void storeInt32(std::int32_t* p, Double8 a) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(p),
                      _mm512_maskz_cvtpd_epi32(static_cast<__mmask8>(0xFF), a.v));
}

}  // namespace
}  // namespace cardemo::batch_detail
