#pragma once
/// Separating-axis test between two 2D oriented boxes (4 axes).

#include "geometry/obb2.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// Boolean SAT: true when the boxes touch or overlap. Cheapest query; early-outs on the first gap.
[[nodiscard]] bool overlapObb2(const Obb2& a, const Obb2& b);

/// SAT with separation and unit normal from A towards B (the contract's `hit,sep,nx,ny`).
/// Works in A's frame after one double subtraction of the centres, so it is accurate far from the
/// origin. Ties between axes prefer A's axes, then B's, in order x, y.
[[nodiscard]] SatResult2 collideObb2(const Obb2& a, const Obb2& b);

}  // namespace cardemo
