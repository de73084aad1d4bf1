// Fuzz target: the 3D separating-axis routines (collideObb3, overlapObb3) against the exact GMP
// oracle (src/compare/exact), in both argument orders, and the batch kernels (overlapObb3Batch,
// separationObb3Batch) and the lab's one-pair vector forms on the same pair on every batch path.
//
// Input: byte 0 picks the domain (bit 7: "wild"); then A's centre, rotation and size, B's rotation
// (often nearly or exactly parallel to A's) and size, and B's placement (shapes3.hpp).
// In the contract's domain a wrong answer aborts: `hit` wrong while |exact sep| > 1e-6 m, `sep`
// more than 2e-6 m from the exact value, a normal that is not unit or does not realise `sep` from
// A towards B, `hit` not equal to `sep <= 0`, or NaN/inf; for the batch kernels, a path whose hit
// or separation differs from the portable path's in any bit (the SIMD paths put a float
// pre-filter before the boolean kernel), or a hit not equal to its separation's `sep <= 0`.
// Outside it: no NaN/inf, no crash.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "fuzz_check.hpp"
#include "geometry/batch_path.hpp"
#include "geometry/bit_cast.hpp"
#include "lab/geometry/obb3_paths.hpp"
#include "lab/kernels/obb3_batch.hpp"
#include "shapes3.hpp"

namespace cardemo::fuzz {
namespace {

constexpr double kHitTolerance = 1e-6;  // CONTRACT.md, "Pair queries"
constexpr double kSepTolerance = 2e-6;

std::string context(const Obb3& a, const Obb3& b, const SatResult3& r) {
  std::ostringstream out;
  out.precision(17);
  out << "\n  A: " << describe(a) << "\n  B: " << describe(b) << "\n  result: hit " << r.hit
      << " sep " << r.separation << " normal (" << r.normal.transpose() << ") axis "
      << r.axis_index;
  return out.str();
}

void requireFinite(const Obb3& a, const Obb3& b, const SatResult3& r) {
  require(std::isfinite(r.separation) && r.normal.allFinite(),
          "NaN or infinity" + context(a, b, r));
}

void requireAccurate(const Obb3& a, const Obb3& b, const SatResult3& r,
                     const exact::ExactResult& ex) {
  std::ostringstream truth;
  truth.precision(17);
  truth << "\n  exact: hit " << ex.hit << " sep " << ex.separation;
  const std::string why = context(a, b, r) + truth.str();
  if (std::abs(ex.separation) > kHitTolerance) {
    require(r.hit == ex.hit, "hit is wrong" + why);
    require(overlapObb3(a, b) == ex.hit, "overlapObb3 is wrong" + why);
  }
  require(std::abs(r.separation - ex.separation) <= kSepTolerance, "sep is off" + why);
  require(r.hit == (r.separation <= 0.0), "hit disagrees with its own sep" + why);
  require(std::abs(r.normal.norm() - 1.0) <= 1e-12, "normal is not unit" + why);
  const Eigen::Vector3d d = b.center - a.center;
  const double along = d.dot(r.normal) - supportRadius(a, r.normal) - supportRadius(b, r.normal);
  require(std::abs(along - r.separation) <= kSepTolerance,
          "the normal does not realise sep from A to B (gap along it " + std::to_string(along) +
              ")" + why);
}

// The batch kernels on B alone and on B among shifted copies (so that its lane group holds other
// pairs), on every path this CPU has, against the portable path's bits.
void requireBatchAgrees(const Obb3& a, const Obb3& b, bool checked) {
  std::vector<Obb3> boxes{b};
  for (const double shift : {1e-7, -1e-4, 3.0}) {
    Obb3 c = b;
    c.center.x() += shift;
    boxes.push_back(c);
  }
  const Obb3Batch many(boxes);
  const BatchPath saved = batchPath();
  std::vector<std::uint8_t> first_hit;
  std::vector<double> first_sep;
  for (const BatchPath path : {BatchPath::kPortable, BatchPath::kAvx2, BatchPath::kAvx512}) {
    if (!batchPathAvailable(path)) continue;
    setBatchPath(path);
    std::vector<std::uint8_t> hit(boxes.size(), 7);
    std::vector<double> sep(boxes.size());
    static_cast<void>(overlapObb3Batch(a, many, hit));
    separationObb3Batch(a, many, sep);
    if (!checked) continue;
    // The lab's one-pair vector forms give src's bits on every path.
    const SatResult3 one = collideObb3OnPath(a, b), want = collideObb3(a, b);
    require(one.axis_index == want.axis_index &&
                bitCast<std::uint64_t>(one.separation) == bitCast<std::uint64_t>(want.separation) &&
                one.normal == want.normal && overlapObb3OnPath(a, b) == overlapObb3(a, b),
            std::string("collideObb3OnPath differs from collideObb3 on the ") +
                batchPathName(path) + " path\n  A: " + describe(a) + "\n  B: " + describe(b));
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::string where = std::string(" on the ") + batchPathName(path) + " path, box " +
                                std::to_string(i) + "\n  A: " + describe(a) +
                                "\n  B: " + describe(boxes[i]);
      require(std::isfinite(sep[i]), "batch separation is not finite" + where);
      require(hit[i] == (sep[i] <= 0.0 ? 1 : 0), "batch hit disagrees with batch sep" + where);
      if (!first_hit.empty()) {
        require(hit[i] == first_hit[i], "batch hit differs from the portable path's" + where);
        require(bitCast<std::uint64_t>(sep[i]) == bitCast<std::uint64_t>(first_sep[i]),
                "batch sep differs from the portable path's" + where);
      }
    }
    if (first_hit.empty()) {
      first_hit = hit;
      first_sep = sep;
    }
  }
  setBatchPath(saved);
}

}  // namespace
}  // namespace cardemo::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cardemo;
  using namespace cardemo::fuzz;
  ByteReader in(data, size);
  const bool wild = (in.byte() & 0x80) != 0;
  BoxDecoder3 decode(in, wild);
  const Eigen::Vector3d ca = decode.center();
  const Eigen::Quaterniond qa = decode.rotation();
  const Obb3 a = Obb3::fromQuaternion(ca, qa, decode.size());
  const Eigen::Quaterniond qb = decode.rotationFrom(qa);
  Obb3 b = Obb3::fromQuaternion(Eigen::Vector3d::Zero(), qb, decode.size());
  decode.place(a, b);
  if (!b.center.allFinite()) return 0;  // wild placement beyond double range: not an input
  const SatResult3 ab = collideObb3(a, b), ba = collideObb3(b, a);
  requireFinite(a, b, ab);
  requireFinite(b, a, ba);
  static_cast<void>(overlapObb3(a, b));
  static_cast<void>(overlapObb3(b, a));
  requireBatchAgrees(a, b, !wild);
  if (wild) return 0;
  const exact::ExactResult ex = exact::collideObb3(a, b);
  requireAccurate(a, b, ab, ex);
  requireAccurate(b, a, ba, ex);
  return 0;
}
