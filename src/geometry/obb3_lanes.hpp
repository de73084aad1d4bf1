#pragma once
/// Internal to obb3.cpp: the common case of overlapObb3 and collideObb3 (face gaps, and edge gaps
/// in A's frame) with one AVX2 register per 3-vector, chosen at run time (geometry/batch_path).
/// Every lane does the SSE2 path's operations in its order, so the numbers are the same bit for
/// bit.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as kernels/batch_entry.hpp).

namespace cardemo::obb3_detail {

/// A box as plain numbers: its centre (3), half extents (3) and rotation (9, column-major).
struct BoxNumbers {
  const double* center;    ///< x, y, z, metres.
  const double* half;      ///< Half extents along the box's axes, metres.
  const double* rotation;  ///< Columns are the box's axes, world frame.
};

/// What decides overlapObb3 in the common case: the largest of the six face gaps and, when that is
/// not positive, the largest of the nine A-frame edge gaps (unnormalised), both metres.
struct OverlapGaps {
  double face;  ///< Largest face gap.
  double edge;  ///< Largest edge gap times its axis length; unset when face > 0.
};

/// overlapObb3's face and fast edge gaps. Call only when geometry/batch_path says the CPU has AVX2.
void overlapGapsAvx2(const BoxNumbers& a, const BoxNumbers& b, OverlapGaps& out);

/// collideObb3's root-free comparison of two candidate separations (the AVX2 kernel's) is certain
/// when its two products differ by more than this fraction of the first (obb3.cpp gives the
/// argument); otherwise the kernel normalises the gaps and picks as a scan in axis order does.
inline constexpr double kCertain = 0x1p-48;

/// collideObb3's common case: the largest of the fifteen gaps (faces 0-5, edges 6 + 3i + j) with
/// every edge gap in A's frame, normalised: the first largest in axis order, bit for bit what
/// obb3.cpp's SSE2 path (largestNormalised) finds, though compared without roots where certain.
struct LargestGap {
  double gap;  ///< The largest gap, metres.
  int axis;    ///< Its axis index (SatResult3::axis_index).
  // The pose, for the winner's normal: bit for bit obb3.cpp's Pose3 (lane 3 of each is padding).
  double t[4];       ///< a_k . d, d = cB - cA.
  double tb[4];      ///< b_j . d.
  double col[3][4];  ///< col[j][k] = r_kj = a_k . b_j.
};

/// collideObb3's largest gap, when every edge gap clears the filter: |gap| > bound and squared axis
/// length > min_length2 (obb3.cpp, rootFreeBound and EdgeFilter). False otherwise, with only the
/// pose written. Call only when geometry/batch_path says the CPU has AVX2.
bool largestGapAvx2(const BoxNumbers& a, const BoxNumbers& b, double bound, double min_length2,
                    LargestGap& out);

}  // namespace cardemo::obb3_detail
