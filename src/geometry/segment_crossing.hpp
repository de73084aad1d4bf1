#pragma once
/// Exact meeting tests of a segment with a segment or a convex quadrilateral (closed sets: a
/// touching end point or edge counts), from the exact orientation signs of geometry/exact_sign.

#include <Eigen/Core>
#include <array>

namespace cardemo {

/// The closed segments p0-p1 and a-b share at least one point (either may be a single point).
[[nodiscard]] bool segmentsMeet(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                                const Eigen::Vector2d& a, const Eigen::Vector2d& b);

/// Point p lies in the closed convex quadrilateral `corners` (counter-clockwise).
[[nodiscard]] bool quadContains(const std::array<Eigen::Vector2d, 4>& corners,
                                const Eigen::Vector2d& p);

/// The closed segment p0-p1 meets the closed convex quadrilateral `corners` (counter-clockwise).
[[nodiscard]] bool segmentMeetsQuad(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                                    const std::array<Eigen::Vector2d, 4>& corners);

}  // namespace cardemo
