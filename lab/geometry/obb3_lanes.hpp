#pragma once
/// Internal to obb3_paths.cpp: the common case of overlapObb3 and collideObb3 (face gaps, and edge
/// gaps in A's frame) with one AVX2 register per 3-vector, chosen at run time
/// (geometry/batch_path). Every lane does src/geometry/obb3.cpp's operations in its order, so the
/// numbers are the same bit for bit.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as lab/kernels/batch_entry.hpp).

#include "geometry/obb3_edge_bound.hpp"

namespace cardemo::obb3_detail {

/// overlapAvx2's verdict.
enum class Verdict { kSeparated, kOverlapping, kUndecided };

/// overlapObb3's common case: separated on a face axis, or decided by every fast edge gap clearing
/// the filter for the larger frame defect `phi` (edgeBound); undecided otherwise. `a`
/// and `b` hold BoxNumbers. Call only when geometry/batch_path says the CPU has AVX2.
Verdict overlapAvx2(const double* a, const double* b, double phi);
/// overlapAvx2 built with AVX-512VL: the same verdicts. Call only on the kAvx512 batch path.
Verdict overlapAvx512(const double* a, const double* b, double phi);

/// collideObb3's root-free comparison of two candidate separations (the AVX2 kernel's) is certain
/// when its two products differ by more than this fraction of the first (obb3_paths.cpp gives the
/// argument); otherwise the kernel normalises the gaps and picks as a scan in axis order does.
inline constexpr double kCertain = 0x1p-48;

/// The pair's scale (EdgeBound::scale) within which collideObb3's root-free comparison holds
/// (obb3_paths.cpp gives the range): a pair outside takes the edge-by-edge loop.
inline constexpr double kRootFreeMinScale = 0x1p-400;
/// Upper end of that range.
inline constexpr double kRootFreeMaxScale = 0x1p400;

/// collideObb3's common case: the largest of the fifteen gaps (faces 0-5, edges 6 + 3i + j) with
/// every edge gap in A's frame, normalised: the first largest in axis order, bit for bit what
/// src/geometry/obb3.cpp (largestNormalised) finds, though compared without roots where certain.
struct LargestGap {
  double gap;  ///< The largest gap, metres.
  int axis;    ///< Its axis index (SatResult3::axis_index).
  // The pose, for the winner's normal: bit for bit src/geometry/obb3.cpp's Pose3 (lane 3 of each is
  // padding).
  double t[4];       ///< a_k . d, d = cB - cA.
  double tb[4];      ///< b_j . d.
  double col[3][4];  ///< col[j][k] = r_kj = a_k . b_j.
};

/// collideObb3's largest gap, when every edge gap clears the filter for the larger frame defect
/// `phi`: |gap| > bound and squared axis length > min_length2 (edgeBound; no bound
/// outside kRootFreeMinScale..kRootFreeMaxScale). False otherwise, with only the pose written. `a`
/// and `b` hold BoxNumbers. Call only when geometry/batch_path says the CPU has AVX2.
bool largestGapAvx2(const double* a, const double* b, double phi, LargestGap& out);
/// largestGapAvx2 built with AVX-512VL: the same bits. Call only on the kAvx512 batch path.
bool largestGapAvx512(const double* a, const double* b, double phi, LargestGap& out);

}  // namespace cardemo::obb3_detail
