#pragma once
/// Two doubles operated on together: one SSE2 register on x86-64 (part of the baseline, so no
/// dispatch and no -march), two plain doubles elsewhere. Both forms do the same IEEE operations
/// lane by lane, min and max included (x86's minpd/maxpd semantics), so results never depend on
/// which one is built.

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cardemo::simd {

#if defined(__SSE2__)

/// Two doubles in one SSE2 register.
struct Double2 {
  __m128d v;  ///< Lane 0 low, lane 1 high.
};

/// Both lanes from a 16-byte aligned address.
[[gnu::always_inline]] inline Double2 loadAligned(const double* p) {
  return {_mm_load_pd(p)};
}
/// Both lanes from any address.
[[gnu::always_inline]] inline Double2 load(const double* p) {
  return {_mm_loadu_pd(p)};
}
/// Both lanes to a 16-byte aligned address.
[[gnu::always_inline]] inline void storeAligned(double* p, Double2 a) {
  _mm_store_pd(p, a.v);
}
/// (x, y) as lanes 0 and 1.
[[gnu::always_inline]] inline Double2 make(double x, double y) {
  return {_mm_set_pd(y, x)};
}
/// Lane 0 of a in both lanes.
[[gnu::always_inline]] inline Double2 low(Double2 a) {
  return {_mm_unpacklo_pd(a.v, a.v)};
}
/// Lane 1 of a in both lanes.
[[gnu::always_inline]] inline Double2 high(Double2 a) {
  return {_mm_unpackhi_pd(a.v, a.v)};
}
/// Lane-wise a + b.
[[gnu::always_inline]] inline Double2 operator+(Double2 a, Double2 b) {
  return {_mm_add_pd(a.v, b.v)};
}
/// Lane-wise a - b.
[[gnu::always_inline]] inline Double2 operator-(Double2 a, Double2 b) {
  return {_mm_sub_pd(a.v, b.v)};
}
/// Lane-wise a * b.
[[gnu::always_inline]] inline Double2 operator*(Double2 a, Double2 b) {
  return {_mm_mul_pd(a.v, b.v)};
}
/// Lane-wise a / b.
[[gnu::always_inline]] inline Double2 operator/(Double2 a, Double2 b) {
  return {_mm_div_pd(a.v, b.v)};
}
/// Lane-wise a < b ? a : b.
[[gnu::always_inline]] inline Double2 min(Double2 a, Double2 b) {
  return {_mm_min_pd(a.v, b.v)};
}
/// Lane-wise a > b ? a : b.
[[gnu::always_inline]] inline Double2 max(Double2 a, Double2 b) {
  return {_mm_max_pd(a.v, b.v)};
}
/// Lane-wise |a| (the sign bit cleared).
[[gnu::always_inline]] inline Double2 abs(Double2 a) {
  return {_mm_andnot_pd(_mm_set1_pd(-0.0), a.v)};
}
/// Lane 0.
[[gnu::always_inline]] inline double lane0(Double2 a) {
  return _mm_cvtsd_f64(a.v);
}
/// Lane 1.
[[gnu::always_inline]] inline double lane1(Double2 a) {
  return _mm_cvtsd_f64(_mm_unpackhi_pd(a.v, a.v));
}
/// (lane 0 of a, lane 0 of b).
[[gnu::always_inline]] inline Double2 lows(Double2 a, Double2 b) {
  return {_mm_unpacklo_pd(a.v, b.v)};
}
/// (lane 1 of a, lane 1 of b).
[[gnu::always_inline]] inline Double2 highs(Double2 a, Double2 b) {
  return {_mm_unpackhi_pd(a.v, b.v)};
}
/// (lane 0 of a, lane 1 of b).
[[gnu::always_inline]] inline Double2 blend(Double2 a, Double2 b) {
  return {_mm_move_sd(b.v, a.v)};
}

#else

/// Two doubles.
struct Double2 {
  double v[2];  ///< Lanes 0 and 1.
};

/// Both lanes from a 16-byte aligned address.
inline Double2 loadAligned(const double* p) {
  return {{p[0], p[1]}};
}
/// Both lanes from any address.
inline Double2 load(const double* p) {
  return {{p[0], p[1]}};
}
/// Both lanes to a 16-byte aligned address.
inline void storeAligned(double* p, Double2 a) {
  p[0] = a.v[0];
  p[1] = a.v[1];
}
/// (x, y) as lanes 0 and 1.
inline Double2 make(double x, double y) {
  return {{x, y}};
}
/// Lane 0 of a in both lanes.
inline Double2 low(Double2 a) {
  return {{a.v[0], a.v[0]}};
}
/// Lane 1 of a in both lanes.
inline Double2 high(Double2 a) {
  return {{a.v[1], a.v[1]}};
}
/// Lane-wise a + b.
inline Double2 operator+(Double2 a, Double2 b) {
  return {{a.v[0] + b.v[0], a.v[1] + b.v[1]}};
}
/// Lane-wise a - b.
inline Double2 operator-(Double2 a, Double2 b) {
  return {{a.v[0] - b.v[0], a.v[1] - b.v[1]}};
}
/// Lane-wise a * b.
inline Double2 operator*(Double2 a, Double2 b) {
  return {{a.v[0] * b.v[0], a.v[1] * b.v[1]}};
}
/// Lane-wise a / b.
inline Double2 operator/(Double2 a, Double2 b) {
  return {{a.v[0] / b.v[0], a.v[1] / b.v[1]}};
}
/// Lane-wise a < b ? a : b.
inline Double2 min(Double2 a, Double2 b) {
  return {{a.v[0] < b.v[0] ? a.v[0] : b.v[0], a.v[1] < b.v[1] ? a.v[1] : b.v[1]}};
}
/// Lane-wise a > b ? a : b.
inline Double2 max(Double2 a, Double2 b) {
  return {{a.v[0] > b.v[0] ? a.v[0] : b.v[0], a.v[1] > b.v[1] ? a.v[1] : b.v[1]}};
}
/// Lane-wise |a| (the sign bit cleared).
inline Double2 abs(Double2 a) {
  return {{__builtin_fabs(a.v[0]), __builtin_fabs(a.v[1])}};
}
/// Lane 0.
inline double lane0(Double2 a) {
  return a.v[0];
}
/// Lane 1.
inline double lane1(Double2 a) {
  return a.v[1];
}
/// (lane 0 of a, lane 0 of b).
inline Double2 lows(Double2 a, Double2 b) {
  return {{a.v[0], b.v[0]}};
}
/// (lane 1 of a, lane 1 of b).
inline Double2 highs(Double2 a, Double2 b) {
  return {{a.v[1], b.v[1]}};
}
/// (lane 0 of a, lane 1 of b).
inline Double2 blend(Double2 a, Double2 b) {
  return {{a.v[0], b.v[1]}};
}

#endif

}  // namespace cardemo::simd
