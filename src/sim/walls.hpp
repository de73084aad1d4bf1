#pragma once
/// The four edges of a scene's bounds as walls: their ids, normals and how far a car reaches
/// into each.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/aabb.hpp"

namespace cardemo {

/// A wall of the scene's bounds, in the order of their collider indices (after the parked cars
/// and obstacles).
enum class WallSide : std::uint8_t { kWest, kEast, kSouth, kNorth };

/// Number of walls a scene with bounds has.
inline constexpr std::size_t kWallCount = 4;

/// Every wall, in index order.
inline constexpr std::array<WallSide, kWallCount> kWallSides{WallSide::kWest, WallSide::kEast,
                                                             WallSide::kSouth, WallSide::kNorth};

/// The id a wall's hits carry: "bounds-west", "bounds-east", "bounds-south", "bounds-north".
[[nodiscard]] const std::string& wallId(WallSide side);

/// Unit normal from the inside of the bounds towards the wall: (-1, 0) for the west wall, ...
[[nodiscard]] Eigen::Vector2d wallNormal(WallSide side);

/// How far `box` reaches past each wall's line, metres, in kWallSides order: >= 0 when it touches
/// or crosses the wall, < 0 when apart (the west wall's: walls.min.x - box.min.x). A box is exactly
/// the car's tight bounds, so this is exactly how far its furthest corner reaches.
[[nodiscard]] std::array<double, kWallCount> wallDepths(const Aabb2& box, const Aabb2& walls);

}  // namespace cardemo
