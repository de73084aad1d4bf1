#pragma once
/// Internal to obb3.cpp: the common case of overlapObb3 and collideObb3 (face gaps, and edge gaps
/// in A's frame) with one AVX2 register per 3-vector, chosen at run time (geometry/batch_path).
/// Every lane does the SSE2 path's operations in its order, so the numbers are the same bit for
/// bit.
//
// Free of Eigen and of the standard library's inline code, so the AVX2 translation unit
// instantiates nothing the linker could share with the rest (as kernels/batch_entry.hpp).

namespace cardemo::obb3_detail {

/// A box as plain numbers, Obb3's first fifteen doubles: its centre (0-2, metres), half extents
/// (3-5, metres, along the box's axes) and rotation (6-14, column-major: columns are the box's
/// axes, world frame).
struct BoxNumbers {
  static constexpr int kCenter = 0;    ///< Offset of the centre.
  static constexpr int kHalf = 3;      ///< Offset of the half extents.
  static constexpr int kRotation = 6;  ///< Offset of the rotation.
};

/// overlapAvx2's verdict.
enum class Verdict { kSeparated, kOverlapping, kUndecided };

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

/// overlapObb3's common case: separated on a face axis, or decided by every fast edge gap clearing
/// the filter for the larger frame defect `phi` (edgeBound); undecided otherwise. `a`
/// and `b` hold BoxNumbers. Call only when geometry/batch_path says the CPU has AVX2.
Verdict overlapAvx2(const double* a, const double* b, double phi);
/// overlapAvx2 built with AVX-512VL: the same verdicts. Call only on the kAvx512 batch path.
Verdict overlapAvx512(const double* a, const double* b, double phi);

/// collideObb3's root-free comparison of two candidate separations (the AVX2 kernel's) is certain
/// when its two products differ by more than this fraction of the first (obb3.cpp gives the
/// argument); otherwise the kernel normalises the gaps and picks as a scan in axis order does.
inline constexpr double kCertain = 0x1p-48;

/// The pair's scale (EdgeBound::scale) within which collideObb3's root-free comparison holds
/// (obb3.cpp gives the range): a pair outside takes the edge-by-edge loop.
inline constexpr double kRootFreeMinScale = 0x1p-400;
/// Upper end of that range.
inline constexpr double kRootFreeMaxScale = 0x1p400;

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

/// collideObb3's largest gap, when every edge gap clears the filter for the larger frame defect
/// `phi`: |gap| > bound and squared axis length > min_length2 (edgeBound; no bound
/// outside kRootFreeMinScale..kRootFreeMaxScale). False otherwise, with only the pose written. `a`
/// and `b` hold BoxNumbers. Call only when geometry/batch_path says the CPU has AVX2.
bool largestGapAvx2(const double* a, const double* b, double phi, LargestGap& out);
/// largestGapAvx2 built with AVX-512VL: the same bits. Call only on the kAvx512 batch path.
bool largestGapAvx512(const double* a, const double* b, double phi, LargestGap& out);

}  // namespace cardemo::obb3_detail
