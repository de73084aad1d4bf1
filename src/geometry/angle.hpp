#pragma once
/// Angles: unit vectors that keep axis-aligned headings exact, the wraps, degree conversions.

#include <Eigen/Core>
#include <numbers>

namespace cardemo {

/// Degrees in `radians` (multiplied by the one rounded factor 180/pi).
[[nodiscard]] constexpr double degreesFromRadians(double radians) {
  return radians * (180.0 / std::numbers::pi);
}

/// Radians in `degrees` (multiplied by the one rounded factor pi/180).
[[nodiscard]] constexpr double radiansFromDegrees(double degrees) {
  return degrees * (std::numbers::pi / 180.0);
}

/// Unit vector (cos, sin) of an angle in degrees; exact at multiples of 90 degrees, because the
/// argument is reduced in degrees before converting to radians.
[[nodiscard]] Eigen::Vector2d unitFromDegrees(double degrees);

/// Unit vector (cos, sin) of an angle in radians.
[[nodiscard]] Eigen::Vector2d unitFromRadians(double radians);

/// Wraps an angle in radians into (-pi, pi], exactly (the one wrap of angles in radians).
[[nodiscard]] double wrapRadians(double radians);

/// Wraps an angle in degrees into (-180, 180], exactly (the one wrap of angles in degrees).
[[nodiscard]] double wrapDegrees(double degrees);

/// Angle of a direction in degrees in (-180, 180].
[[nodiscard]] double degreesOf(const Eigen::Vector2d& direction);

}  // namespace cardemo
