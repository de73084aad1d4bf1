// Separating-axis tests between convex polygons and boxes (declared in convex_polygon.hpp).
//
// Each candidate axis is an unnormalised edge normal (the edge vector turned a quarter turn) or a
// box axis, so on inputs whose products are exact (a grid) every gap is exact too. Two axes are
// measured at a time (simd::Double2), the axes are ordered without a root or a division by their
// length per axis, and only the winner is normalised.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/convex_polygon.hpp"
#include "geometry/double2.hpp"
#include "geometry/finite.hpp"
#include "geometry/sat_fast_range.hpp"

namespace cardemo {
namespace {

using simd::Double2;

constexpr int kMaxPoints = ConvexPolygon::kMaxVertices;
constexpr double kPlusInfinity = std::numeric_limits<double>::infinity();
constexpr double kMinusInfinity = -kPlusInfinity;
constexpr int kMaxSlots = 2 * kMaxPoints;  // both shapes' axes, each padded to an even count

// One shape in the pair's frame (coordinates relative to the reference point) and its own axes.
struct Shape {
  // Points: x[k], y[k] for k < count, repeated cyclically up to 2*count so that any run of
  // consecutive vertices is one load; and each coordinate in both lanes (xx[k] = {x_k, x_k}).
  alignas(16) double x[2 * kMaxPoints];
  alignas(16) double y[2 * kMaxPoints];
  alignas(16) double xx[kMaxPoints][2];
  alignas(16) double yy[kMaxPoints][2];
  int count = 0;
  Double2 largest = simd::make(0.0, 0.0);  // largest |x|, |y|
  // Axes: a polygon's edge normals (axis i belongs to the edge from vertex i to vertex i+1) or a
  // box's two axes; an odd count is padded with a copy of the last axis, whose result is unused.
  alignas(16) double nx[kMaxPoints];
  alignas(16) double ny[kMaxPoints];
  int axis_count = 0;
  bool is_polygon = false;
};

[[gnu::always_inline]] inline void addPoint(Double2 p, Shape& s) {
  const int k = s.count++;
  simd::storeAligned(s.xx[k], simd::low(p));
  simd::storeAligned(s.yy[k], simd::high(p));
  s.x[k] = simd::lane0(p);
  s.y[k] = simd::lane1(p);
  s.largest = simd::max(s.largest, simd::abs(p));
}

// Repeats the points cyclically and pads the axes to an even count.
void finish(Shape& s) {
  for (int k = 0; k < s.count; ++k) {
    s.x[s.count + k] = s.x[k];
    s.y[s.count + k] = s.y[k];
  }
  if (s.axis_count % 2 == 1) {
    s.nx[s.axis_count] = s.nx[s.axis_count - 1];
    s.ny[s.axis_count] = s.ny[s.axis_count - 1];
  }
}

// kCount > 0: the polygon's vertex count, known at compile time (the loop unrolls).
template <int kCount>
void fillPolygon(PolygonView p, const Eigen::Vector2d& ref, Shape& s) {
  const int count = kCount > 0 ? kCount : p.count;
  const Double2 r = simd::load(ref.data());
  const Double2 first = simd::load(p.vertex(0).data());
  Double2 v = first;
  Double2 largest = simd::make(0.0, 0.0);
  for (int i = 0; i < count; ++i) {
    const Double2 next = i + 1 < count ? simd::load(p.vertex(i + 1).data()) : first;
    const Double2 local = v - r;
    simd::storeAligned(s.xx[i], simd::low(local));
    simd::storeAligned(s.yy[i], simd::high(local));
    s.x[i] = s.x[i + count] = simd::lane0(local);
    s.y[i] = s.y[i + count] = simd::lane1(local);
    largest = simd::max(largest, simd::abs(local));
    // The edge from the world coordinates (far from the origin this difference is exact, by
    // Sterbenz's lemma) turned clockwise: (next.y - v.y, v.x - next.x), the outward normal of a
    // CCW polygon.
    s.nx[i] = simd::lane1(next - v);
    s.ny[i] = simd::lane0(v - next);
    v = next;
  }
  if (count % 2 == 1) {
    s.nx[count] = s.nx[count - 1];
    s.ny[count] = s.ny[count - 1];
  }
  s.count = count;
  s.axis_count = count;
  s.largest = largest;
  s.is_polygon = true;
}

Shape polygonShape(PolygonView p, const Eigen::Vector2d& ref) {
  Shape s;
  if (p.count == 4) {
    fillPolygon<4>(p, ref, s);
  } else {
    fillPolygon<0>(p, ref, s);
  }
  return s;
}

Shape boxShape(const Obb2& b, const Eigen::Vector2d& ref) {
  Shape s;
  const Eigen::Vector2d c = b.center - ref;  // subtract in double first (STYLE 8)
  const Eigen::Vector2d ex = b.axis * b.half.x();
  const Eigen::Vector2d ey = b.perp() * b.half.y();
  const Eigen::Vector2d corners[4] = {c + ex - ey, c + ex + ey, c - ex + ey, c - ex - ey};
  for (const Eigen::Vector2d& corner : corners) addPoint(simd::load(corner.data()), s);
  // A box's opposite faces share an axis, so two axes cover its four edge normals.
  s.nx[0] = b.axis.x();
  s.ny[0] = b.axis.y();
  s.nx[1] = -b.axis.y();
  s.ny[1] = b.axis.x();
  s.axis_count = 2;
  finish(s);
  return s;
}

double largestCoordinate(const Shape& s) {
  return std::max(simd::lane0(s.largest), simd::lane1(s.largest));
}

// Per slot (A's axes, then B's, each padded to an even count): the gap with B on the axis's
// positive side (forward) and on its negative side (backward), and the key that orders the axes by
// normalised gap. The gap on an axis of squared length L is g / sqrt(L), g = max(forward,
// backward); the key g|g| / L is its square with its sign, an increasing function of it, so the
// largest key marks the largest normalised gap without a root per axis.
struct Measured {
  alignas(16) double forward[kMaxSlots];
  alignas(16) double backward[kMaxSlots];
  alignas(16) double key[kMaxSlots];
  int slots = 0;
  Double2 largest_key = simd::make(kMinusInfinity, kMinusInfinity);
  Double2 smallest_length2 = simd::make(kPlusInfinity, kPlusInfinity);
};

struct Extent2 {
  Double2 lo, hi;
};

// What is known about a shape at compile time: a box (four points, two axes), a quadrilateral
// (four points, four edge normals) or any polygon (counts read at run time). Known counts let the
// loops unroll.
struct AnyPolygon {
  static constexpr int kPoints = 0, kAxes = 0;
  static constexpr bool kPolygon = true;
};
struct Quadrilateral {
  static constexpr int kPoints = 4, kAxes = 4;
  static constexpr bool kPolygon = true;
};
struct Box {
  static constexpr int kPoints = 4, kAxes = 2;
  static constexpr bool kPolygon = false;
};

// Smallest and largest projection of all the points on two axes.
template <class Kind>
[[gnu::always_inline]] inline Extent2 project(const Shape& s, Double2 nx, Double2 ny) {
  const int count = Kind::kPoints > 0 ? Kind::kPoints : s.count;
  Double2 d = nx * simd::loadAligned(s.xx[0]) + ny * simd::loadAligned(s.yy[0]);
  Extent2 e{d, d};
  for (int k = 1; k < count; ++k) {
    d = nx * simd::loadAligned(s.xx[k]) + ny * simd::loadAligned(s.yy[k]);
    e.lo = simd::min(e.lo, d);
    e.hi = simd::max(e.hi, d);
  }
  return e;
}

// A polygon's extent on its own edge normals q and q+1: the largest projection is the edge's own
// first vertex (both ends of an edge project alike; this one is a load away), the smallest is
// among the other count-2 vertices.
template <class Kind>
[[gnu::always_inline]] inline Extent2 projectOwn(const Shape& s, int q, Double2 nx, Double2 ny) {
  if constexpr (!Kind::kPolygon) {
    return project<Kind>(s, nx, ny);
  } else {
    const int count = Kind::kPoints > 0 ? Kind::kPoints : s.count;
    Extent2 e;
    e.hi = nx * simd::load(s.x + q) + ny * simd::load(s.y + q);
    e.lo = nx * simd::load(s.x + q + 2) + ny * simd::load(s.y + q + 2);
    for (int j = 3; j < count; ++j) {
      e.lo = simd::min(e.lo, nx * simd::load(s.x + q + j) + ny * simd::load(s.y + q + j));
    }
    return e;
  }
}

// Measures `own`'s axes against the pair into slots [first, first + own's padded axis count);
// kOwnIsA orients forward from A towards B.
template <class Own, class Other, bool kOwnIsA>
[[gnu::always_inline]] inline void measureAxesOf(const Shape& own, const Shape& other, int first,
                                                 Measured& m, Double2& largest, Double2& smallest) {
  const int axes = Own::kAxes > 0 ? Own::kAxes : own.axis_count;
  for (int q = 0; q < axes; q += 2) {
    const Double2 nx = simd::loadAligned(own.nx + q), ny = simd::loadAligned(own.ny + q);
    const Extent2 s = projectOwn<Own>(own, q, nx, ny);
    const Extent2 o = project<Other>(other, nx, ny);
    const Double2 forward = kOwnIsA ? o.lo - s.hi : s.lo - o.hi;
    const Double2 backward = kOwnIsA ? s.lo - o.hi : o.lo - s.hi;
    const Double2 gap = simd::max(forward, backward);
    const Double2 length2 = nx * nx + ny * ny;
    Double2 key = gap * simd::abs(gap) / length2;
    // A padding axis's own extent is not its edge's: it never wins.
    if (Own::kAxes == 0 && q + 1 == axes) key = simd::make(simd::lane0(key), kMinusInfinity);
    simd::storeAligned(m.forward + first + q, forward);
    simd::storeAligned(m.backward + first + q, backward);
    simd::storeAligned(m.key + first + q, key);
    largest = simd::max(largest, key);
    smallest = simd::min(smallest, length2);
  }
}

template <class KindA, class KindB>
[[gnu::noinline]] void measureAxes(const Shape& a, const Shape& b, Measured& m) {
  Double2 largest = simd::make(kMinusInfinity, kMinusInfinity);
  Double2 smallest = simd::make(kPlusInfinity, kPlusInfinity);
  const int a_slots = a.axis_count + a.axis_count % 2;
  measureAxesOf<KindA, KindB, true>(a, b, 0, m, largest, smallest);
  measureAxesOf<KindB, KindA, false>(b, a, a_slots, m, largest, smallest);
  m.slots = a_slots + b.axis_count + b.axis_count % 2;
  m.largest_key = largest;
  m.smallest_length2 = smallest;
}

template <class KindA>
void measureAgainst(const Shape& a, const Shape& b, Measured& m) {
  if (!b.is_polygon) return measureAxes<KindA, Box>(a, b, m);
  if (b.count == 4) return measureAxes<KindA, Quadrilateral>(a, b, m);
  measureAxes<KindA, AnyPolygon>(a, b, m);
}

Measured measure(const Shape& a, const Shape& b) {
  Measured m;
  if (!a.is_polygon) {
    measureAgainst<Box>(a, b, m);
  } else if (a.count == 4) {
    measureAgainst<Quadrilateral>(a, b, m);
  } else {
    measureAgainst<AnyPolygon>(a, b, m);
  }
  return m;
}

// Axis components of slot `i`.
Eigen::Vector2d slotAxis(const Shape& a, const Shape& b, int i) {
  const int a_slots = a.axis_count + a.axis_count % 2;
  return i < a_slots ? Eigen::Vector2d(a.nx[i], a.ny[i])
                     : Eigen::Vector2d(b.nx[i - a_slots], b.ny[i - a_slots]);
}

// The first slot with the largest key, normalised and pointing from A towards B.
SatResult2 winner(const Shape& a, const Shape& b, const Measured& m) {
  const double largest = std::max(simd::lane0(m.largest_key), simd::lane1(m.largest_key));
  int w = 0;
  while (w + 1 < m.slots && !(m.key[w] == largest)) ++w;
  const Eigen::Vector2d n = slotAxis(a, b, w);
  const double forward = m.forward[w], backward = m.backward[w];
  const double gap = forward > backward ? forward : backward;  // as simd::max
  const double length = std::sqrt(n.x() * n.x() + n.y() * n.y());
  SatResult2 r;
  r.separation = gap / length;
  r.normal = (forward >= backward ? n : Eigen::Vector2d(-n)) / length;
  r.hit = r.separation <= 0.0;
  return r;
}

// Coordinates below 2^100 and squared axis lengths above 2^-200 keep every product and key of
// measureAxes between 2^-1000 and 2^+620: no overflow, and no underflow that could matter.
using sat_detail::kLargestFastCoordinate;
using sat_detail::kSmallestFastLength2;

// `s` with its points scaled by 2^-k and each axis scaled to unit order on its own (zero axes stay
// zero), the points repeated and the axes padded as before.
Shape rescaled(const Shape& s, int k) {
  Shape out = s;
  out.largest = simd::make(0.0, 0.0);
  out.count = 0;
  for (int i = 0; i < s.count; ++i) {
    addPoint(simd::make(std::scalbn(s.x[i], -k), std::scalbn(s.y[i], -k)), out);
  }
  for (int i = 0; i < s.axis_count + s.axis_count % 2; ++i) {
    const double m = std::max(std::abs(s.nx[i]), std::abs(s.ny[i]));
    const int e = m > 0.0 ? std::ilogb(m) : 0;
    out.nx[i] = std::scalbn(s.nx[i], -e);
    out.ny[i] = std::scalbn(s.ny[i], -e);
  }
  finish(out);
  return out;
}

// Extreme magnitudes: the same computation on the shapes scaled by 2^-k to unit order (exact, bar
// underflow of coordinates far below the largest one), every axis scaled to unit order on its own
// (neither a normalised gap nor the order of the keys depends on an axis's length) and zero axes
// dropped (a zero edge has no normal; fewer axes can only report overlap, never a false gap).
// Powers of two commute with every rounding, so the answer is exactly 2^k times the one the fast
// path gives at unit scale.
SatResult2 collideRescaled(const Shape& a, const Shape& b) {
  const double largest = std::max(largestCoordinate(a), largestCoordinate(b));
  const int k = largest > 0.0 ? std::ilogb(largest) : 0;
  const Shape sa = rescaled(a, k), sb = rescaled(b, k);
  Measured m = measure(sa, sb);
  double largest_key = kMinusInfinity;
  for (int i = 0; i < m.slots; ++i) {
    const Eigen::Vector2d n = slotAxis(sa, sb, i);
    if (n.x() == 0.0 && n.y() == 0.0) m.key[i] = kMinusInfinity;
    largest_key = std::max(largest_key, m.key[i]);
  }
  if (!(largest_key > kMinusInfinity)) return {true, 0.0, Eigen::Vector2d::UnitX()};
  m.largest_key = simd::make(largest_key, largest_key);
  SatResult2 r = winner(sa, sb, m);
  r.separation = std::scalbn(r.separation, k);
  r.hit = r.separation <= 0.0;  // a tiny gap may round to zero when scaled back
  return r;
}

SatResult2 collide(const Shape& a, const Shape& b) {
  if (std::max(largestCoordinate(a), largestCoordinate(b)) < kLargestFastCoordinate) {
    const Measured m = measure(a, b);
    const double smallest =
        std::min(simd::lane0(m.smallest_length2), simd::lane1(m.smallest_length2));
    if (smallest > kSmallestFastLength2) {
      SatResult2 r = winner(a, b, m);
      assert(isFinite(r));
      return r;
    }
  }
  SatResult2 r = collideRescaled(a, b);
  assert(isFinite(r));
  return r;
}

// Any two polygons, through Shapes.
[[gnu::noinline]] SatResult2 collideGeneral(PolygonView a, PolygonView b) {
  const Eigen::Vector2d& ref = a.vertex(0);
  return collide(polygonShape(a, ref), polygonShape(b, ref));
}

}  // namespace

SatResult2 collidePolygons(PolygonView a, PolygonView b) {
  assert(inDomain(a) && inDomain(b));
  return collideGeneral(a, b);
}

SatResult2 collidePolygonObb(PolygonView a, const Obb2& b) {
  assert(inDomain(a) && inDomain(b));
  const Eigen::Vector2d& ref = a.vertex(0);
  return collide(polygonShape(a, ref), boxShape(b, ref));
}

SatResult2 collideObbPolygon(const Obb2& a, PolygonView b) {
  assert(inDomain(a) && inDomain(b));
  const Eigen::Vector2d& ref = a.center;
  return collide(boxShape(a, ref), polygonShape(b, ref));
}

}  // namespace cardemo
