#include "lab/geometry/obb3_paths.hpp"

#include <algorithm>
#include <cassert>

#include "geometry/batch_path.hpp"
#include "geometry/finite.hpp"
#include "geometry/obb3_normal.hpp"
#include "lab/geometry/obb3_lanes.hpp"

namespace cardemo {
namespace {

// collideObb3's vector kernel (obb3_vector_kernels.hpp, largestGapVector) compares candidate
// separations without roots (the batch kernels' Candidate, lab/kernels/batch_kernels.hpp): gap /
// sqrt(length2) is carried as gap, length2 and square = gap |gap|, and as z -> z|z| is increasing,
// y's separation is the larger iff y.square * x.length2 > x.square * y.length2. A face enters with
// length2 = 1. One root and one division remain, for the winner only, which reports gap /
// sqrt(length2) as before.
//
// Range: on this path every edge gap has |gap| > bound >= 2^-49 scale, and 2^-14 <= min_length2
// < length2 < 2.01 (phi <= 2^-30 keeps |r_kj| <= 1 + 2^-29); every gap, face or edge, is at most
// 4 scale in magnitude (|t_k| and |along| at most 2.01 |d|_1, the radii at most 1.01 times the
// half extents' sum). So for 2^-400 <= scale <= 2^400 no product exceeds 2^6 scale^2 <= 2^806,
// and an edge's is at least 2^-112 scale^2 >= 2^-912, a normal number: each product is within
// 2^-52 (relative) of its exact value. A face's product that is not a normal number (|gap| below
// about 2^-504) is below 2^-1022, far from the edge product it is compared with. The boxes' domain
// (kMaxCoordinate, half extents down to zero) reaches beyond that range: such a pair takes the
// edge-by-edge loop (obb3_detail::kRootFreeMinScale and kRootFreeMaxScale).

// A step of the comparison is certain when its two products differ by more than 2^-48 of the
// first (a sign apart included): the exact separations then differ by more than 12 u (u = 2^-53),
// and gap / sqrt(length2), within 2 u of its exact value, orders the two the same way, strictly.
// When every step is certain, the winner is the axis that normalising every gap and scanning in
// axis order picks (the tournament's runs are consecutive, and comparisons of doubles are
// transitive), bit for bit; otherwise the kernel normalises and scans too. So its result is always
// that of the portable path (src/geometry/obb3.cpp, largestNormalised), near ties included: the
// root-free pick pays for itself only where a blend instruction selects (SSE2 has none).

#if defined(CARDEMO_BATCH_AVX2)
// The box's obb3_detail::BoxNumbers: its members are three runs of doubles, in that order, with no
// padding between them.
const double* numbersOf(const Obb3& box) {
  const double* numbers = box.center.data();
  assert(box.half.data() == numbers + obb3_detail::BoxNumbers::kHalf &&
         box.rotation().data() == numbers + obb3_detail::BoxNumbers::kRotation);
  return numbers;
}

// The vector kernels for a path other than the portable one: on kAvx512 their AVX-512VL build
// (obb3_vector_kernels.hpp; the same bits).
obb3_detail::Verdict overlapOnPath(BatchPath path, const double* a, const double* b, double phi) {
#if defined(CARDEMO_BATCH_AVX512)
  if (path == BatchPath::kAvx512) return obb3_detail::overlapAvx512(a, b, phi);
#endif
  (void)path;
  return obb3_detail::overlapAvx2(a, b, phi);
}

bool largestGapOnPath(BatchPath path, const double* a, const double* b, double phi,
                      obb3_detail::LargestGap& out) {
#if defined(CARDEMO_BATCH_AVX512)
  if (path == BatchPath::kAvx512) return obb3_detail::largestGapAvx512(a, b, phi, out);
#endif
  (void)path;
  return obb3_detail::largestGapAvx2(a, b, phi, out);
}

// The pose entries largestGapAvx2 stores, as a Pose3 reads them.
struct StoredPose {
  const obb3_detail::LargestGap& g;
  [[nodiscard]] double r(int k, int j) const { return g.col[j][k]; }
  [[nodiscard]] double tk(int k) const { return g.t[k]; }
  [[nodiscard]] double tbk(int j) const { return g.tb[j]; }
};

#endif

}  // namespace

SatResult3 collideObb3OnPath(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
#if defined(CARDEMO_BATCH_AVX2)
  if (const BatchPath path = batchPath(); path != BatchPath::kPortable) {
    obb3_detail::LargestGap largest;
    if (largestGapOnPath(path, numbersOf(a), numbersOf(b),
                         std::max(a.frameDefect(), b.frameDefect()), largest)) {
      SatResult3 r;
      r.separation = largest.gap;
      r.axis_index = largest.axis;
      r.normal = obb3_detail::winningNormal(a, b, StoredPose{largest}, largest.axis);
      r.hit = r.separation <= 0.0;
      assert(isFinite(r));
      return r;
    }
    // Some edge gap lies within the bound (or the scale is outside the root-free range): the
    // portable code takes the edges one by one.
  }
#endif
  return collideObb3(a, b);
}

bool overlapObb3OnPath(const Obb3& a, const Obb3& b) {
  assert(inDomain(a) && inDomain(b));
#if defined(CARDEMO_BATCH_AVX2)
  if (const BatchPath path = batchPath(); path != BatchPath::kPortable) {
    const obb3_detail::Verdict verdict =
        overlapOnPath(path, numbersOf(a), numbersOf(b), std::max(a.frameDefect(), b.frameDefect()));
    if (verdict != obb3_detail::Verdict::kUndecided) {
      return verdict == obb3_detail::Verdict::kOverlapping;
    }
    // Some edge gap lies within the bound: the portable code decides it axis by axis.
  }
#endif
  return overlapObb3(a, b);
}

}  // namespace cardemo
