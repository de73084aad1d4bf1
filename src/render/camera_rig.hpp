#pragma once
/// The game camera: looks ahead along the car's velocity, follows it smoothly, zooms out with
/// speed, starts at a zoom fitted to the scene and never shows the void beyond the walls. Stepped
/// once per simulated frame (frames, not wall time), so a replay frame is framed the same way
/// every time.

#include <optional>

#include "geometry/aabb.hpp"
#include "render/camera.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Tuning of the rig.
struct CameraRigSettings {
  double look_ahead_s = 0.55;       ///< The view leads the car by its velocity times this, seconds.
  double max_look_ahead_m = 14.0;   ///< Cap of the lead, metres.
  double follow_time_s = 0.22;      ///< Time constant of the smoothing of the centre, seconds.
  double zoom_time_s = 0.6;         ///< Time constant of the speed zoom, seconds.
  double zoom_out_per_mps = 0.018;  ///< Zoom is divided by 1 + this x speed (m/s).
  double min_speed_zoom = 0.55;     ///< The speed zoom never goes below this factor.
  double min_fit_ppm = 24.0;        ///< The fitted zoom is raised to at least this (on big lots
                                    ///< a 4.5 m car stays 108 px long), pixels per metre.
  double max_fit_ppm = 40.0;        ///< and lowered to at most this, pixels per metre.
  double fit_margin = 1.04;         ///< The fitted view is this much larger than the scene.
  /// Frame the scene in the viewport minus the HUD's strips (hudInsets): the fit, the car's place
  /// (the middle of what is left) and the clamp, which then lets the walls' outside show only
  /// under those strips. Off: the whole viewport.
  bool clear_hud = true;
};

/// Pixels per metre at which `area` (world metres) fits inside `viewport`, less the strips
/// `insets` at its top and bottom, with `margin` to spare.
[[nodiscard]] double fittedZoom(const Aabb2& area, const Eigen::Vector2i& viewport,
                                double margin = 1.0, const ViewInsets& insets = {});

/// What the camera may show of a scene: the walls' outer edges, or, without walls, nothing (no
/// clamp).
[[nodiscard]] std::optional<Aabb2> cameraBounds(const Scene& scene);

/// Everything of the scene: walls, the player's start, parked cars and obstacles.
[[nodiscard]] Aabb2 sceneExtent(const Scene& scene);

/// Moves `camera.center` so the view, less the strips `insets`, stays inside `bounds`; along an
/// axis where the bounds are smaller than that, centres them in it instead.
[[nodiscard]] Camera clampToBounds(Camera camera, const Aabb2& bounds,
                                   const ViewInsets& insets = {});

/// The rig. reset() snaps it to the world; step() after each World::step moves it smoothly.
class CameraRig {
 public:
  /// A rig on `world` as it is now, with a base zoom fitted to its scene in `viewport`.
  CameraRig(const World& world, const Eigen::Vector2i& viewport,
            const CameraRigSettings& settings = {});

  /// Snaps to the car with no lag (start, restart).
  void reset(const World& world);
  /// Follows one simulated step.
  void step(const World& world);

  /// The camera to draw with: the state between the last two steps at `alpha` (0..1), zoom times
  /// `user_zoom` (the + and - keys), the aim in the middle of the view clear of the HUD, the
  /// screen offset `shake_px` added, then clamped to the walls.
  [[nodiscard]] Camera camera(const Eigen::Vector2i& viewport, double alpha = 1.0,
                              double user_zoom = 1.0,
                              const Eigen::Vector2f& shake_px = Eigen::Vector2f::Zero()) const;

  /// Pixels per metre before the speed zoom and the user's factor.
  [[nodiscard]] double baseZoom() const { return base_ppm_; }
  /// Sets the base zoom (e.g. `render --zoom`).
  void setBaseZoom(double pixels_per_metre) { base_ppm_ = pixels_per_metre; }
  /// Where the view is aiming (the car plus its look-ahead), world metres.
  [[nodiscard]] const Eigen::Vector2d& target() const { return target_; }
  /// Current (smoothed) centre before clamping, world metres.
  [[nodiscard]] const Eigen::Vector2d& center() const { return center_; }
  /// Current speed zoom factor (1 at rest, smaller when fast).
  [[nodiscard]] double speedZoom() const { return speed_zoom_; }

 private:
  [[nodiscard]] Eigen::Vector2d aim(const World& world) const;
  [[nodiscard]] ViewInsets insets(const Eigen::Vector2i& viewport) const;

  CameraRigSettings settings_;
  std::optional<Aabb2> bounds_;
  double base_ppm_ = 12.0;
  Eigen::Vector2d target_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d center_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d previous_center_ = Eigen::Vector2d::Zero();
  double speed_zoom_ = 1.0;
  double previous_speed_zoom_ = 1.0;
};

}  // namespace cardemo
