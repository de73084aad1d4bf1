#include "lab/geometry/collide_quads.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "geometry/batch_path.hpp"
#include "geometry/double2.hpp"
#include "geometry/finite.hpp"
#include "geometry/sat_fast_range.hpp"
#include "lab/geometry/sat_quads.hpp"

namespace cardemo {
namespace {

using sat_detail::kLargestFastCoordinate;
using sat_detail::kSmallestFastLength2;
using simd::Double2;

constexpr double kPlusInfinity = std::numeric_limits<double>::infinity();
constexpr double kMinusInfinity = -kPlusInfinity;

// The winning axis of a pair before normalisation: its gap with B on its positive side (forward)
// and on its negative side (backward), and the axis (an edge vector turned clockwise).
struct AxisGaps {
  double forward, backward, axis_x, axis_y;
};

// Two polygons of kN vertices each, without copying either into a Shape. The pair is symmetric,
// so one register holds both: lane 0 measures A's edge normal q against B and lane 1 B's edge
// normal q against A, with the operations of sat_polygon.cpp's measureAxes in its order (same
// answer bit for bit). False, with nothing written, when the pair is outside the fast path's range.
template <int kN>
bool widestGapOfEqualCounts(PolygonView a, PolygonView b, AxisGaps& out) {
  const Double2 ref = simd::load(a.vertex(0).data());
  // Per vertex i: own = (A's, B's) coordinate, other = (B's, A's); per edge i: its normal.
  Double2 own_x[kN], own_y[kN], other_x[kN], other_y[kN], nx[kN], ny[kN];
  Double2 largest = simd::make(0.0, 0.0);
  for (int i = 0; i < kN; ++i) {
    const Double2 va = simd::load(a.vertex(i).data()), vb = simd::load(b.vertex(i).data());
    const Double2 wa = simd::load(a.vertex((i + 1) % kN).data());
    const Double2 wb = simd::load(b.vertex((i + 1) % kN).data());
    const Double2 la = va - ref, lb = vb - ref;
    largest = simd::max(largest, simd::max(simd::abs(la), simd::abs(lb)));
    own_x[i] = simd::lows(la, lb);
    own_y[i] = simd::highs(la, lb);
    other_x[i] = simd::lows(lb, la);
    other_y[i] = simd::highs(lb, la);
    // As sat_polygon.cpp's fillPolygon: (next.y - v.y, v.x - next.x) from world coordinates.
    nx[i] = simd::highs(wa - va, wb - vb);
    ny[i] = simd::lows(va - wa, vb - wb);
  }
  alignas(16) double forward[kN][2], backward[kN][2], key[kN][2];
  Double2 largest_key = simd::make(kMinusInfinity, kMinusInfinity);
  Double2 smallest_length2 = simd::make(kPlusInfinity, kPlusInfinity);
  for (int q = 0; q < kN; ++q) {
    const Double2 x = nx[q], y = ny[q];
    const Double2 hi = x * own_x[q] + y * own_y[q];
    Double2 lo = x * own_x[(q + 2) % kN] + y * own_y[(q + 2) % kN];
    for (int j = 3; j < kN; ++j)
      lo = simd::min(lo, x * own_x[(q + j) % kN] + y * own_y[(q + j) % kN]);
    Double2 other_lo = x * other_x[0] + y * other_y[0];
    Double2 other_hi = other_lo;
    for (int k = 1; k < kN; ++k) {
      const Double2 d = x * other_x[k] + y * other_y[k];
      other_lo = simd::min(other_lo, d);
      other_hi = simd::max(other_hi, d);
    }
    // Towards B: A's forward gap is B's low end past A's high end; B's is the other way round.
    const Double2 u = other_lo - hi, v = lo - other_hi;
    const Double2 f = simd::blend(u, v), g = simd::blend(v, u);
    const Double2 gap = simd::max(f, g);
    const Double2 length2 = x * x + y * y;
    const Double2 k = gap * simd::abs(gap) / length2;
    simd::storeAligned(forward[q], f);
    simd::storeAligned(backward[q], g);
    simd::storeAligned(key[q], k);
    largest_key = simd::max(largest_key, k);
    smallest_length2 = simd::min(smallest_length2, length2);
  }
  if (!(std::max(simd::lane0(largest), simd::lane1(largest)) < kLargestFastCoordinate &&
        std::min(simd::lane0(smallest_length2), simd::lane1(smallest_length2)) >
            kSmallestFastLength2)) {
    return false;
  }
  // As sat_polygon.cpp's winner(): the first slot (A's axes, then B's) with the largest key.
  const double top = std::max(simd::lane0(largest_key), simd::lane1(largest_key));
  int w = 0;
  while (w + 1 < 2 * kN && !(key[w % kN][w / kN] == top)) ++w;
  const int q = w % kN, lane = w / kN;
  out = {forward[q][lane], backward[q][lane], lane == 0 ? simd::lane0(nx[q]) : simd::lane1(nx[q]),
         lane == 0 ? simd::lane0(ny[q]) : simd::lane1(ny[q])};
  return true;
}

// The winning axis normalised, as sat_polygon.cpp's winner() does it.
sat_detail::WidestAxis normalised(const AxisGaps& w) {
  const double f = w.forward, g = w.backward, n_x = w.axis_x, n_y = w.axis_y;
  const double length = std::sqrt(n_x * n_x + n_y * n_y);
  const double separation = (f > g ? f : g) / length;
  return f >= g ? sat_detail::WidestAxis{separation, n_x / length, n_y / length}
                : sat_detail::WidestAxis{separation, -n_x / length, -n_y / length};
}

// Two quadrilaterals on the SSE2 path. Not inlined, as src's general path is not: the AVX2 path's
// caller then keeps a small frame (no callee-saved registers, no room for two Shapes).
[[gnu::noinline]] bool widestAxisOfQuadsSse2(PolygonView a, PolygonView b,
                                             sat_detail::WidestAxis& out) {
  AxisGaps gaps;
  if (!widestGapOfEqualCounts<4>(a, b, gaps)) return false;
  out = normalised(gaps);
  return true;
}

// Two quadrilaterals on the widest path the CPU has (both give the same bits).
bool widestAxisOfQuads(PolygonView a, PolygonView b, sat_detail::WidestAxis& out) {
#if defined(CARDEMO_BATCH_AVX2)
  const BatchPath path = batchPath();
#if defined(CARDEMO_BATCH_AVX512)
  if (path == BatchPath::kAvx512) {
    return sat_detail::widestAxisOfQuadsAvx512(a.vertex(0).data(), b.vertex(0).data(), out);
  }
#endif
  if (path != BatchPath::kPortable) {
    return sat_detail::widestAxisOfQuadsAvx2(a.vertex(0).data(), b.vertex(0).data(), out);
  }
#endif
  return widestAxisOfQuadsSse2(a, b, out);
}

}  // namespace

SatResult2 collideQuads(PolygonView a, PolygonView b) {
  assert(inDomain(a) && inDomain(b));
  sat_detail::WidestAxis widest;
  if (a.count == 4 && b.count == 4 && widestAxisOfQuads(a, b, widest)) {
    SatResult2 r{widest.separation <= 0.0, widest.separation,
                 Eigen::Vector2d(widest.normal_x, widest.normal_y)};
    assert(isFinite(r));
    return r;
  }
  return collidePolygons(a, b);
}

}  // namespace cardemo
