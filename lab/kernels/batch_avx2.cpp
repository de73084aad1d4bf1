// The batch kernels four pairs at a time with AVX2 (+ FMA for the explicit fma of the 3D edge
// axes). Built with -mavx2 -mfma (lab/CMakeLists.txt) and called only after batchPathAvailable says
// the CPU has both, so the default build still runs on any x86-64.
//
// Includes nothing but the intrinsics and the kernel header (no Eigen, no <cmath>): an inline
// function instantiated here with AVX2 encodings could otherwise be picked by the linker for the
// whole program.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "batch_avx2.cpp needs -mavx2 -mfma (set in lab/CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "lab/kernels/batch_kernels.hpp"
#include "lab/kernels/manifold2_lanes.hpp"

namespace cardemo::batch_detail {
namespace {

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

}  // namespace

void overlap2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit) {
  runOverlap2<Lane4>(a, b, first, last, hit);
}

void collide2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  const Sat2Out& out) {
  runCollide2<Lane4>(a, b, first, last, out);
}

void manifold2Avx2(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                   std::size_t first, std::size_t last, const Manifold2Out& out) {
  runManifold2<Lane4>(a, b, settings, first, last, out);
}

void overlap3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit) {
  runOverlap3<Lane4>(a, b, first, last, hit);
}

void separation3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                     double* separation) {
  runSeparation3<Lane4>(a, b, first, last, separation);
}

}  // namespace cardemo::batch_detail

#endif
