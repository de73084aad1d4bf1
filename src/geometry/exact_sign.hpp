#pragma once
/// Exact signs of small polynomials in doubles (orientation, dot products), by error-free
/// products and sums of doubles (Shewchuk, "Adaptive Precision Floating-Point Arithmetic", 1997).
/// Exact while no product of two inputs is below 1e-290 in magnitude (a tail would underflow)
/// and none overflows.

#include <Eigen/Core>
#include <span>
#include <utility>

namespace cardemo {

/// One term a * b of a sum of products.
using ProductTerm = std::pair<double, double>;

/// The exact sign (-1, 0 or +1) of the sum of the products a * b over `terms` (at most 8).
[[nodiscard]] int signOfProductSum(std::span<const ProductTerm> terms);

/// The exact sign of the orientation of c against the directed line a -> b: +1 when c lies to its
/// left (a, b, c counter-clockwise), -1 to its right, 0 on the line.
[[nodiscard]] int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                              const Eigen::Vector2d& c);

/// The exact sign of dot(to - from, direction).
[[nodiscard]] int signOfAdvance(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                const Eigen::Vector2d& direction);

}  // namespace cardemo
