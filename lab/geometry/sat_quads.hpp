#pragma once
/// Internal to collide_quads.cpp: the separating-axis test of two quadrilaterals four axes at a
/// time with AVX2, chosen at run time (geometry/batch_path) as the grid scan is.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as lab/kernels/batch_entry.hpp).

#include "geometry/sat_fast_range.hpp"

namespace cardemo::sat_detail {

/// The winning axis of a pair, normalised: the separation along it and its unit normal, pointing
/// from A towards B.
struct WidestAxis {
  double separation;  ///< Largest normalised gap, metres; <= 0 means the pair touches or overlaps.
  double normal_x;    ///< Unit normal from A towards B, x.
  double normal_y;    ///< Unit normal, y.
};

/// The first of the eight edge normals (A's, then B's) with the largest normalised gap between
/// quadrilaterals `a` and `b` (four CCW vertices each, x0, y0, ..., x3, y3, world metres),
/// normalised, bit for bit as the SSE2 path of collide_quads.cpp finds it. False, with nothing
/// written, when the pair is outside the fast path's range. Call only when geometry/batch_path
/// says the CPU has AVX2.
bool widestAxisOfQuadsAvx2(const double* a, const double* b, WidestAxis& out);
/// widestAxisOfQuadsAvx2 built with AVX-512VL: the same bits. Call only on the kAvx512 batch path.
bool widestAxisOfQuadsAvx512(const double* a, const double* b, WidestAxis& out);

}  // namespace cardemo::sat_detail
