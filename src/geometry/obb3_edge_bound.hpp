#pragma once
/// Internal to obb3.cpp and to the lab's vector kernels of the same queries
/// (lab/geometry/obb3_lanes.hpp): a box as plain numbers and the A-frame filter of the edge gaps,
/// one definition for both so that they agree bit for bit.
//
// Free of Eigen and of the standard library's inline code, so that a translation unit built for
// another instruction set instantiates nothing the linker could share with the rest.

namespace cardemo::obb3_detail {

/// A box as plain numbers, Obb3's first fifteen doubles: its centre (0-2, metres), half extents
/// (3-5, metres, along the box's axes) and rotation (6-14, column-major: columns are the box's
/// axes, world frame).
struct BoxNumbers {
  static constexpr int kCenter = 0;    ///< Offset of the centre.
  static constexpr int kHalf = 3;      ///< Offset of the half extents.
  static constexpr int kRotation = 6;  ///< Offset of the rotation.
};

/// The A-frame filter of obb3.cpp's edge gaps (obb3.cpp gives the argument).
struct EdgeBound {
  double bound;        ///< On |gap times axis length|, metres.
  double min_length2;  ///< Floor on the squared axis length for a normalised fast gap.
  double scale;        ///< The pair's scale, metres (infinite with the bound).
};

/// The edge filter for boxes `a` and `b` (BoxNumbers) and their larger frame defect `phi`: every
/// field infinite when phi > 2^-30. Internal linkage, so that the AVX2 file's copy is never the
/// one the other files call.
[[gnu::always_inline]] static inline EdgeBound edgeBound(const double* a, const double* b,
                                                         double phi) {
  constexpr double kU = 0x1p-53;
  if (!(phi <= 0x1p-30)) return {__builtin_inf(), __builtin_inf(), __builtin_inf()};
  const double *ca = a + BoxNumbers::kCenter, *cb = b + BoxNumbers::kCenter;
  const double *ha = a + BoxNumbers::kHalf, *hb = b + BoxNumbers::kHalf;
  // The pair's scale: it bounds |d|, each projected radius and so each gap on a unit axis.
  const double scale = __builtin_fabs(cb[0] - ca[0]) + __builtin_fabs(cb[1] - ca[1]) +
                       __builtin_fabs(cb[2] - ca[2]) + (ha[0] + ha[1] + ha[2]) +
                       (hb[0] + hb[1] + hb[2]);
  const double root = (64.0 * kU + 8.0 * phi) / 0x1p-40;
  return {(32.0 * kU + 6.0 * phi) * scale, root * root, scale};
}

}  // namespace cardemo::obb3_detail
