#include "geometry/obb2.hpp"

#include <cmath>

#include "geometry/angle.hpp"

namespace cardemo {

Obb2 Obb2::fromDegrees(const Eigen::Vector2d& center, double heading_deg, double length,
                       double width) {
  return {center, unitFromDegrees(heading_deg), {0.5 * length, 0.5 * width}};
}

std::array<Eigen::Vector2d, 4> Obb2::corners() const {
  const Eigen::Vector2d ex = axis * half.x();
  const Eigen::Vector2d ey = perp() * half.y();
  return {center + ex - ey, center + ex + ey, center - ex + ey, center - ex - ey};
}

Aabb2 Obb2::aabb() const {
  const Eigen::Vector2d r{std::abs(axis.x()) * half.x() + std::abs(axis.y()) * half.y(),
                          std::abs(axis.y()) * half.x() + std::abs(axis.x()) * half.y()};
  return {center - r, center + r};
}

}  // namespace cardemo
