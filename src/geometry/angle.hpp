#pragma once
/// Angle helpers that keep axis-aligned headings exact.

#include <Eigen/Core>

namespace cardemo {

/// Unit vector (cos, sin) of an angle in degrees; exact at multiples of 90 degrees, because the
/// argument is reduced in degrees before converting to radians.
[[nodiscard]] Eigen::Vector2d unitFromDegrees(double degrees);

/// Unit vector (cos, sin) of an angle in radians.
[[nodiscard]] Eigen::Vector2d unitFromRadians(double radians);

/// Wraps an angle in radians into (-pi, pi].
[[nodiscard]] double wrapRadians(double radians);

/// Angle of a direction in degrees in (-180, 180].
[[nodiscard]] double degreesOf(const Eigen::Vector2d& direction);

}  // namespace cardemo
