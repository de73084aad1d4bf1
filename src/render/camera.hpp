#pragma once
/// World-to-screen mapping: follows the car, zooms, flips +y up to screen-down.

#include <Eigen/Core>

namespace cardemo {

/// Pixels across the top and the bottom of a viewport that overlays cover (the HUD's strips).
struct ViewInsets {
  float top = 0.0f;     ///< Height of the strip at the top, pixels.
  float bottom = 0.0f;  ///< Height of the strip at the bottom, pixels.
};

/// A view of the world. Positions are subtracted in double before converting to float, so the
/// picture is as sharp at 1e7 m from the origin as at the origin.
struct Camera {
  Eigen::Vector2d center =
      Eigen::Vector2d::Zero();          ///< World point at the middle of the view, metres.
  double pixels_per_metre = 12.0;       ///< Zoom.
  Eigen::Vector2i viewport{1280, 720};  ///< Size in pixels.

  /// Pixel position of a world point (y flipped: +y is up in the world, down on screen).
  [[nodiscard]] Eigen::Vector2f toScreen(const Eigen::Vector2d& world) const {
    const double sx = (world.x() - center.x()) * pixels_per_metre + 0.5 * viewport.x();
    const double sy = (center.y() - world.y()) * pixels_per_metre + 0.5 * viewport.y();
    return {static_cast<float>(sx), static_cast<float>(sy)};
  }
  /// World point under a pixel.
  [[nodiscard]] Eigen::Vector2d toWorld(const Eigen::Vector2f& screen) const {
    return {center.x() + (screen.x() - 0.5 * viewport.x()) / pixels_per_metre,
            center.y() - (screen.y() - 0.5 * viewport.y()) / pixels_per_metre};
  }
};

}  // namespace cardemo
