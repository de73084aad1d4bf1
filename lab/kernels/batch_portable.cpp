// The batch kernels one pair at a time, in plain C++: the fallback that runs on any CPU.

#include <cmath>

#include "lab/kernels/batch_kernels.hpp"

namespace cardemo::batch_detail {
namespace {

// One double per lane. Masks are bools.
struct Mask1 {
  bool m;
};

struct Lane1 {
  static constexpr std::size_t kWidth = 1;
  using Mask = Mask1;
  double v;
  static Lane1 load(const double* p) { return {*p}; }
  static Lane1 splat(double x) { return {x}; }
};

[[gnu::always_inline]] inline Lane1 operator+(Lane1 a, Lane1 b) {
  return {a.v + b.v};
}
[[gnu::always_inline]] inline Lane1 operator-(Lane1 a, Lane1 b) {
  return {a.v - b.v};
}
[[gnu::always_inline]] inline Lane1 operator*(Lane1 a, Lane1 b) {
  return {a.v * b.v};
}
[[gnu::always_inline]] inline Lane1 operator/(Lane1 a, Lane1 b) {
  return {a.v / b.v};
}
[[gnu::always_inline]] inline Lane1 operator-(Lane1 a) {
  return {-a.v};
}
[[gnu::always_inline]] inline Lane1 abs(Lane1 a) {
  return {std::fabs(a.v)};
}
[[gnu::always_inline]] inline Lane1 sqrt(Lane1 a) {
  return {std::sqrt(a.v)};
}
[[gnu::always_inline]] inline Lane1 fma(Lane1 a, Lane1 b, Lane1 c) {
  return {std::fma(a.v, b.v, c.v)};
}
[[gnu::always_inline]] inline Mask1 gt(Lane1 a, Lane1 b) {
  return {a.v > b.v};
}
[[gnu::always_inline]] inline Mask1 lt(Lane1 a, Lane1 b) {
  return {a.v < b.v};
}
[[gnu::always_inline]] inline Mask1 operator|(Mask1 a, Mask1 b) {
  return {a.m || b.m};
}
[[gnu::always_inline]] inline Mask1 operator&(Mask1 a, Mask1 b) {
  return {a.m && b.m};
}
[[gnu::always_inline]] inline Lane1 select(Mask1 m, Lane1 a, Lane1 b) {
  return m.m ? a : b;
}
[[gnu::always_inline]] inline void store(double* p, Lane1 a) {
  *p = a.v;
}
[[gnu::always_inline]] inline void storeHits(std::uint8_t* p, Mask1 separated) {
  *p = separated.m ? 0 : 1;
}
[[gnu::always_inline]] inline bool allOf(Mask1 m) {
  return m.m;
}

}  // namespace

void overlap2Portable(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                      std::uint8_t* hit) {
  runOverlap2<Lane1>(a, b, first, last, hit);
}

void collide2Portable(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                      const Sat2Out& out) {
  runCollide2<Lane1>(a, b, first, last, out);
}

void overlap3Portable(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                      std::uint8_t* hit) {
  runOverlap3<Lane1>(a, b, first, last, hit);
}

void separation3Portable(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                         double* separation) {
  runSeparation3<Lane1>(a, b, first, last, separation);
}

}  // namespace cardemo::batch_detail
