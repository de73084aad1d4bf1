#include "geometry/angle.hpp"

#include <cmath>
#include <numbers>

#include "geometry/trig.hpp"

namespace cardemo {

Eigen::Vector2d unitFromDegrees(double degrees) {
  // Reduce exactly in degrees (fmod is exact), then pick the quadrant so that 90, 180, 270 give
  // exact unit vectors instead of cos(pi/2) = 6e-17.
  double r = std::fmod(degrees, 360.0);
  if (r < 0) r += 360.0;
  int quadrant = 0;
  while (r >= 90.0 && quadrant < 3) {
    r -= 90.0;
    ++quadrant;
  }
  const double rad = radiansFromDegrees(r);
  const trig::CosSin unit =
      trig::turnedByQuarters(r == 0.0 ? trig::CosSin{1.0, 0.0} : trig::cosSin(rad), quadrant);
  return {unit.cos, unit.sin};
}

Eigen::Vector2d unitFromRadians(double radians) {
  const trig::CosSin unit = trig::cosSin(radians);
  return {unit.cos, unit.sin};
}

double wrapRadians(double radians) {
  // Already in range (every step's heading, nearly always): remainder would return it unchanged,
  // and it is the most expensive call of a step.
  if (radians > -std::numbers::pi && radians <= std::numbers::pi) return radians;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double r = std::remainder(radians, kTwoPi);  // exact, in [-pi, pi]
  if (r <= -std::numbers::pi) r += kTwoPi;
  return r;
}

double wrapDegrees(double degrees) {
  if (degrees > -180.0 && degrees <= 180.0) return degrees;
  double r = std::remainder(degrees, 360.0);  // exact, in [-180, 180]
  if (r <= -180.0) r += 360.0;
  return r;
}

double degreesOf(const Eigen::Vector2d& direction) {
  // atan2 lies in [-pi, pi], and pi * (180 / pi) rounds to 180 exactly: only -180 moves.
  return wrapDegrees(degreesFromRadians(trig::atan2(direction.y(), direction.x())));
}

}  // namespace cardemo
