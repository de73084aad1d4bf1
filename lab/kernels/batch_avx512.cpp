// The batch kernels with AVX-512F: the 2D boolean SAT through the float pre-filter, sixteen pairs
// per instruction, and every double kernel eight pairs per instruction (the 2D SAT with separation
// and normal, the 2D boolean SAT for the boxes the filter leaves undecided, the 2D contact
// manifold, and both 3D kernels with their A-frame filter). Built with -mavx512f
// (lab/CMakeLists.txt) and called only after batchPathAvailable says the CPU has it.
//
// Includes nothing but the intrinsics and the kernel headers, for the reason given in
// batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX512)
#if !defined(__AVX512F__)
#error "batch_avx512.cpp needs -mavx512f (set in lab/CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "lab/kernels/batch2_filter.hpp"
#include "lab/kernels/batch3_filter.hpp"
#include "lab/kernels/batch_kernels.hpp"
#include "lab/kernels/box_fields.hpp"
#include "lab/kernels/filter_run_avx512.hpp"
#include "lab/kernels/manifold2_lanes.hpp"

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

// The 2D boolean kernel prefetches the double fields of the boxes its filter leaves open when
// they take more bytes than this. Measured on the benchmark's boxes (docs/perf/history.md, "2D
// batch kernels"): at 64k boxes (3 MiB) the prefetches cost more than they saved, at 1M (48 MiB)
// they saved about 30 % of the time.
constexpr std::size_t kPrefetchAbove = std::size_t{16} << 20;

std::size_t overlap2FilteredAvx512(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                   const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit) {
  const FilterQuery2<Float16> q = splatQuery<Float16>(fa);
  const Box2FilterArrays filter_arrays = fb;
  const Box2Fields source = fieldsOf(b);
  return runFilteredGathered(
      first, last, hit,
      [q, filter_arrays](std::size_t i) { return filter2<Float16>(q, filter_arrays, i); },
      source.field,
      [&a](const double(&f)[6][8], std::uint8_t* group_hit) {
        storeHits(group_hit, separated2<Double8>(a, arraysOf(f), 0));
      },
      [&source, prefetch = (last - first) * sizeof(double) * 6 > kPrefetchAbove](std::size_t i) {
        // The group's double fields, which the gathers read when the buffer of open boxes is
        // next decided: in a batch larger than the caches those sparse reads would miss. In a
        // smaller one the prefetches cost more than they save.
        if (!prefetch) return;
        for (std::size_t f = 0; f < 6; ++f) {
          __builtin_prefetch(source.field[f] + i);
          __builtin_prefetch(source.field[f] + i + 8);
        }
      });
}

std::size_t overlap3FilteredAvx512(const Box3One& a, const Box3Arrays& b, const Box3FilterOne& fa,
                                   const Box3FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit) {
  // The open boxes are copied lane by lane, not gathered as in the 2D kernel above: with fifteen
  // fields the gathers were slower at 1M boxes (docs/perf/history.md, "2D batch kernels").
  return runFilteredOverlap3<Float16>(
      fa, fb, first, last, hit, [&](const std::size_t* boxes, std::size_t count) {
        decideOpenBoxes<8>(fieldsOf(b).field, boxes, count, hit,
                           [&](const double(&f)[15][8], std::uint8_t* group_hit) {
                             runOverlap3<Double8>(a, arraysOf(f), 0, 8, group_hit);
                           });
      });
}

void overlap2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit) {
  runOverlap2<Double8>(a, b, first, last, hit);
}

void collide2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    const Sat2Out& out) {
  runCollide2<Double8>(a, b, first, last, out);
}

void manifold2Avx512(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                     std::size_t first, std::size_t last, const Manifold2Out& out) {
  runManifold2<Double8>(a, b, settings, first, last, out);
}

void overlap3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit) {
  runOverlap3<Double8>(a, b, first, last, hit);
}

void separation3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                       double* separation) {
  runSeparation3<Double8>(a, b, first, last, separation);
}

}  // namespace cardemo::batch_detail

#endif
