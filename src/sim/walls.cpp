#include "sim/walls.hpp"

namespace cardemo {

const std::string& wallId(WallSide side) {
  static const std::array<std::string, kWallCount> ids{"bounds-west", "bounds-east", "bounds-south",
                                                       "bounds-north"};
  return ids[static_cast<std::size_t>(side)];
}

Eigen::Vector2d wallNormal(WallSide side) {
  switch (side) {
    case WallSide::kWest:
      return {-1.0, 0.0};
    case WallSide::kEast:
      return {1.0, 0.0};
    case WallSide::kSouth:
      return {0.0, -1.0};
    case WallSide::kNorth:
      break;
  }
  return {0.0, 1.0};
}

std::array<double, kWallCount> wallDepths(const Aabb2& box, const Aabb2& walls) {
  return {walls.min.x() - box.min.x(), box.max.x() - walls.max.x(), walls.min.y() - box.min.y(),
          box.max.y() - walls.max.y()};
}

}  // namespace cardemo
