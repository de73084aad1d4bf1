#pragma once
/// Internal to sat_polygon.cpp: the separating-axis test of two quadrilaterals four axes at a time
/// with AVX2, chosen at run time (geometry/batch_path) as the grid scan is.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as kernels/batch_entry.hpp).

namespace cardemo::sat_detail {

/// Coordinates below this (relative to the pair's reference point) keep every product and key of
/// the fast path between 2^-1000 and 2^+620, given squared axis lengths above kSmallestFastLength2.
inline constexpr double kLargestFastCoordinate = 0x1p100;
/// See kLargestFastCoordinate.
inline constexpr double kSmallestFastLength2 = 0x1p-200;

/// The winning axis of a pair: its gap with B on its positive side (forward) and on its negative
/// side (backward), and the axis, unnormalised.
struct AxisGaps {
  double forward;   ///< Gap with B beyond A on +axis.
  double backward;  ///< Gap with B beyond A on -axis.
  double axis_x;    ///< The axis (an edge vector turned clockwise), x.
  double axis_y;    ///< The axis, y.
};

/// The first of the eight edge normals (A's, then B's) with the largest normalised gap between
/// quadrilaterals `a` and `b` (four CCW vertices each, x0, y0, ..., x3, y3, world metres), bit for
/// bit as the SSE2 path of sat_polygon.cpp finds it. False, with nothing written, when the pair is
/// outside the fast path's range. Call only when geometry/batch_path says the CPU has AVX2.
bool widestGapOfQuadsAvx2(const double* a, const double* b, AxisGaps& out);

}  // namespace cardemo::sat_detail
