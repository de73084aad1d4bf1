#pragma once
/// Swept separating-axis test: a 2D box translating against a static 2D box.

#include <Eigen/Core>

#include "geometry/obb2.hpp"
#include "geometry/sweep_result.hpp"

namespace cardemo {

/// First contact of box `a` moving by `displacement` (world metres, over t in [0, 1]) with the
/// static box `b`: exact per-axis intervals on the 4 box axes, no sampling, so no tunnelling at any
/// speed. Works in A's frame after one double subtraction of the centres. Touching counts as
/// contact; contact at t = 0 gives toi = 0 with collideObb2's normal and separation (bit for bit).
[[nodiscard]] SweepResult2 sweepObb2(const Obb2& a, const Eigen::Vector2d& displacement,
                                     const Obb2& b);

}  // namespace cardemo
