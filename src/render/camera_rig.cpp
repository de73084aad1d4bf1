#include "render/camera_rig.hpp"

#include <algorithm>
#include <cmath>

#include "render/hud.hpp"
#include "render/world_layer.hpp"

namespace cardemo {
namespace {

// Share of the remaining distance covered in one step of `dt` with time constant `tau`.
double follow(double dt, double tau) {
  return tau > 0.0 ? 1.0 - std::exp(-dt / tau) : 1.0;
}

}  // namespace

double fittedZoom(const Aabb2& area, const Eigen::Vector2i& viewport, double margin,
                  const ViewInsets& insets) {
  const Eigen::Vector2d size = (area.max - area.min) * std::max(margin, 1.0);
  const double height =
      std::max(1.0, static_cast<double>(viewport.y()) - insets.top - insets.bottom);
  const double zx = size.x() > 0.0 ? viewport.x() / size.x() : 1e9;
  const double zy = size.y() > 0.0 ? height / size.y() : 1e9;
  return std::min(zx, zy);
}

std::optional<Aabb2> cameraBounds(const Scene& scene) {
  if (!scene.bounds) return std::nullopt;
  return Aabb2{scene.bounds->min.array() - kWallThicknessM,
               scene.bounds->max.array() + kWallThicknessM};
}

Aabb2 sceneExtent(const Scene& scene) {
  if (const auto b = cameraBounds(scene)) return *b;
  const Obb2 start = Obb2::fromDegrees(scene.player.position, scene.player.heading_deg,
                                       scene.player.length, scene.player.width);
  Aabb2 all = start.aabb();
  auto grow = [&all](const Aabb2& b) { all = {all.min.cwiseMin(b.min), all.max.cwiseMax(b.max)}; };
  for (const ParkedCar& p : scene.parked) grow(p.box.aabb());
  for (const Obstacle& o : scene.obstacles) grow(o.polygon.aabb());
  return all;
}

Camera clampToBounds(Camera camera, const Aabb2& bounds, const ViewInsets& insets) {
  // The view may reach past the walls by the strips the HUD covers (screen top is world +y), so
  // that what is under them can be brought out; then the view is held inside the grown bounds.
  const double ppm = camera.pixels_per_metre;
  Aabb2 held = bounds;
  held.max.y() += insets.top / ppm;
  held.min.y() -= insets.bottom / ppm;
  for (int axis = 0; axis < 2; ++axis) {
    const double half = 0.5 * camera.viewport[axis] / ppm;
    const double lo = held.min[axis] + half;
    const double hi = held.max[axis] - half;
    camera.center[axis] = lo <= hi ? std::clamp(camera.center[axis], lo, hi)
                                   : 0.5 * (held.min[axis] + held.max[axis]);
  }
  return camera;
}

CameraRig::CameraRig(const World& world, const Eigen::Vector2i& viewport,
                     const CameraRigSettings& settings)
    : settings_(settings), bounds_(cameraBounds(world.scene())) {
  base_ppm_ = std::clamp(
      fittedZoom(sceneExtent(world.scene()), viewport, settings_.fit_margin, insets(viewport)),
      settings_.min_fit_ppm, settings_.max_fit_ppm);
  reset(world);
}

Eigen::Vector2d CameraRig::aim(const World& world) const {
  Eigen::Vector2d lead = world.car().velocity() * settings_.look_ahead_s;
  const double len = lead.norm();
  if (len > settings_.max_look_ahead_m) lead *= settings_.max_look_ahead_m / len;
  return world.car().position + lead;
}

ViewInsets CameraRig::insets(const Eigen::Vector2i& viewport) const {
  return settings_.clear_hud ? hudInsets(viewport) : ViewInsets{};
}

void CameraRig::reset(const World& world) {
  target_ = aim(world);
  center_ = previous_center_ = target_;
  speed_zoom_ = previous_speed_zoom_ =
      std::max(settings_.min_speed_zoom,
               1.0 / (1.0 + settings_.zoom_out_per_mps * std::abs(world.car().speed)));
}

void CameraRig::step(const World& world) {
  const double dt = 1.0 / world.settings().hz;
  previous_center_ = center_;
  previous_speed_zoom_ = speed_zoom_;
  target_ = aim(world);
  center_ += (target_ - center_) * follow(dt, settings_.follow_time_s);
  const double want =
      std::max(settings_.min_speed_zoom,
               1.0 / (1.0 + settings_.zoom_out_per_mps * std::abs(world.car().speed)));
  speed_zoom_ += (want - speed_zoom_) * follow(dt, settings_.zoom_time_s);
}

Camera CameraRig::camera(const Eigen::Vector2i& viewport, double alpha, double user_zoom,
                         const Eigen::Vector2f& shake_px) const {
  const double a = std::clamp(alpha, 0.0, 1.0);
  Camera c;
  c.viewport = viewport;
  const double zoom = previous_speed_zoom_ + (speed_zoom_ - previous_speed_zoom_) * a;
  c.pixels_per_metre = base_ppm_ * zoom * user_zoom;
  c.center = previous_center_ + (center_ - previous_center_) * a;
  // The aim sits in the middle of the view between the HUD's strips: half their difference lower
  // on screen. Screen x right is world +x; screen y down is world -y.
  const ViewInsets hud = insets(viewport);
  const Eigen::Vector2f offset_px = shake_px - Eigen::Vector2f{0.0f, 0.5f * (hud.top - hud.bottom)};
  c.center += Eigen::Vector2d{offset_px.x(), -offset_px.y()} / c.pixels_per_metre;
  return bounds_ ? clampToBounds(c, *bounds_, hud) : c;
}

}  // namespace cardemo
