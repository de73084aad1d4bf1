// Fuzz target: the 2D separating-axis routines (collideObb2, overlapObb2, collidePolygons,
// collideObbPolygon, collidePolygonObb) against the exact GMP oracle (src/compare/exact), in both
// argument orders; the lab's quadrilateral SAT against collidePolygons, bit for bit.
//
// Input: byte 0 picks the routine (bits 0-1: box/box, polygon/polygon, box/polygon, polygon/box)
// and the domain (bit 7: "wild"); then shape A, shape B and B's placement (shapes2.hpp).
// In the contract's domain a wrong answer aborts: `hit` wrong while |exact sep| > 1e-6 m, `sep`
// more than 2e-6 m from the exact value, a normal that is not unit or does not realise `sep` from
// A towards B, `hit` not equal to `sep <= 0`, or NaN/inf. Outside it: no NaN/inf, no crash.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "compare/exact/exact_sat.hpp"
#include "fuzz_check.hpp"
#include "geometry/bit_cast.hpp"
#include "geometry/sat_obb2.hpp"
#include "lab/geometry/collide_quads.hpp"
#include "shapes2.hpp"

namespace cardemo::fuzz {
namespace {

constexpr double kHitTolerance = 1e-6;  // CONTRACT.md, "Pair queries"
constexpr double kSepTolerance = 2e-6;

SatResult2 fast(const Shape2& a, const Shape2& b) {
  if (a.is_box && b.is_box) return collideObb2(a.box, b.box);
  if (a.is_box) return collideObbPolygon(a.box, b.poly);
  if (b.is_box) return collidePolygonObb(a.poly, b.box);
  return collidePolygons(a.poly, b.poly);
}

exact::ExactResult oracle(const Shape2& a, const Shape2& b) {
  if (a.is_box && b.is_box) return exact::collideObb2(a.box, b.box);
  // A box keeps its exact axes: its rounded corners would tilt its faces far from the origin.
  if (a.is_box) return exact::collideObbPolygon(a.box, b.poly);
  if (b.is_box) return exact::collideObbPolygon(b.box, a.poly);
  return exact::collidePolygons(a.poly, b.poly);
}

std::string context(const Shape2& a, const Shape2& b, const SatResult2& r) {
  std::ostringstream out;
  out.precision(17);
  out << "\n  A: " << a.describe() << "\n  B: " << b.describe() << "\n  result: hit " << r.hit
      << " sep " << r.separation << " normal (" << r.normal.x() << ", " << r.normal.y() << ")";
  return out.str();
}

void requireFinite(const Shape2& a, const Shape2& b, const SatResult2& r) {
  require(std::isfinite(r.separation) && r.normal.allFinite(),
          "NaN or infinity" + context(a, b, r));
}

// One argument order against the exact verdict of the pair (the oracle is symmetric).
void requireAccurate(const Shape2& a, const Shape2& b, const SatResult2& r,
                     const exact::ExactResult& ex) {
  std::ostringstream truth;
  truth.precision(17);
  truth << "\n  exact: hit " << ex.hit << " sep " << ex.separation;
  const std::string why = context(a, b, r) + truth.str();
  if (std::abs(ex.separation) > kHitTolerance) require(r.hit == ex.hit, "hit is wrong" + why);
  require(std::abs(r.separation - ex.separation) <= kSepTolerance, "sep is off" + why);
  require(r.hit == (r.separation <= 0.0), "hit disagrees with its own sep" + why);
  require(std::abs(r.normal.norm() - 1.0) <= 1e-12, "normal is not unit" + why);
  const double along = gapAlong(a.points(), b.points(), r.normal, a.anchor());
  require(std::abs(along - r.separation) <= kSepTolerance,
          "the normal does not realise sep from A to B (gap along it " + std::to_string(along) +
              ")" + why);
}

void check(const Shape2& a, const Shape2& b) {
  const SatResult2 ab = fast(a, b), ba = fast(b, a);
  requireFinite(a, b, ab);
  requireFinite(b, a, ba);
  const bool both_boxes = a.is_box && b.is_box;
  if (both_boxes) {
    static_cast<void>(overlapObb2(a.box, b.box));
    static_cast<void>(overlapObb2(b.box, a.box));
  }
  if (!a.in_domain || !b.in_domain) return;
  if (!a.is_box && !b.is_box) {
    // The lab's quadrilateral SAT (lab/geometry/collide_quads) gives collidePolygons' bits.
    const SatResult2 q = collideQuads(a.poly, b.poly);
    require(q.hit == ab.hit &&
                bitCast<std::uint64_t>(q.separation) == bitCast<std::uint64_t>(ab.separation) &&
                q.normal == ab.normal,
            "collideQuads differs from collidePolygons" + context(a, b, ab));
  }
  const exact::ExactResult ex = oracle(a, b);
  requireAccurate(a, b, ab, ex);
  requireAccurate(b, a, ba, ex);
  if (both_boxes && std::abs(ex.separation) > kHitTolerance) {
    require(overlapObb2(a.box, b.box) == ex.hit && overlapObb2(b.box, a.box) == ex.hit,
            "overlapObb2 is wrong" + context(a, b, ab));
  }
}

}  // namespace
}  // namespace cardemo::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cardemo::fuzz;
  ByteReader in(data, size);
  const std::uint8_t selector = in.byte();
  const int routine = selector & 3;
  ShapeDecoder2 decode(in, (selector & 0x80) != 0);
  const auto a = decode.shape(routine == 0 || routine == 2, decode.center());
  if (!a) return 0;
  auto b = decode.shape(routine == 0 || routine == 3, Eigen::Vector2d::Zero());
  if (!b) return 0;
  decode.place(*a, *b);
  if (!b->revalidate()) return 0;
  check(*a, *b);
  return 0;
}
