#pragma once
/// Rigid transforms of whole scenes (translation, rotation, mirror) for the invariance tests.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "geometry/angle.hpp"
#include "sim/input_frame.hpp"
#include "sim/scene.hpp"

namespace cardemo::stress {

/// p -> R(rotate_deg) * M * p + translate, where M mirrors y (y -> -y) when `mirror` is set. A
/// mirrored scene is driven with the inputs mirrored too (left <-> right).
struct RigidTransform {
  Eigen::Vector2d translate = Eigen::Vector2d::Zero();  ///< Metres, applied last.
  double rotate_deg = 0.0;                              ///< Degrees CCW, about the origin.
  bool mirror = false;                                  ///< Reflect y before rotating.

  /// True when the rotation maps axis-aligned boxes onto axis-aligned boxes.
  [[nodiscard]] bool keepsAxes() const { return std::fmod(rotate_deg, 90.0) == 0.0; }
  /// The rotation's (cos, sin), exact at multiples of 90 degrees.
  [[nodiscard]] Eigen::Vector2d rotation() const { return unitFromDegrees(rotate_deg); }
  /// Image of a direction (no translation).
  [[nodiscard]] Eigen::Vector2d direction(const Eigen::Vector2d& v) const {
    const Eigen::Vector2d r = rotation();
    const double y = mirror ? -v.y() : v.y();
    return {r.x() * v.x() - r.y() * y, r.y() * v.x() + r.x() * y};
  }
  /// Image of a hit's collider id: a wall (`bounds-west`, ...) becomes the wall its outward
  /// normal turns into; any other id is its own image.
  [[nodiscard]] std::string colliderImage(const std::string& id) const {
    static const std::array<std::pair<const char*, Eigen::Vector2d>, 4> walls = {
        {{"bounds-west", {-1.0, 0.0}},
         {"bounds-east", {1.0, 0.0}},
         {"bounds-south", {0.0, -1.0}},
         {"bounds-north", {0.0, 1.0}}}};
    for (const auto& [name, normal] : walls) {
      if (id != name) continue;
      const Eigen::Vector2d image = direction(normal);
      for (const auto& [other, other_normal] : walls) {
        if ((image - other_normal).norm() < 1e-9) return other;
      }
    }
    return id;
  }
  /// Image of a point.
  [[nodiscard]] Eigen::Vector2d point(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = direction(p);
    return {d.x() + translate.x(), d.y() + translate.y()};
  }
  /// Preimage of a point (translation removed first, in double, then the rotation undone).
  [[nodiscard]] Eigen::Vector2d inversePoint(const Eigen::Vector2d& q) const {
    const Eigen::Vector2d r = rotation();
    const double x = q.x() - translate.x(), y = q.y() - translate.y();
    const double ux = r.x() * x + r.y() * y, uy = -r.y() * x + r.x() * y;
    return {ux, mirror ? -uy : uy};
  }
  /// Image of a heading in degrees.
  [[nodiscard]] double headingDeg(double deg) const { return (mirror ? -deg : deg) + rotate_deg; }
  /// Image of an angle in radians (heading), before wrapping.
  [[nodiscard]] double headingRad(double rad) const {
    return (mirror ? -rad : rad) + rotate_deg * (3.14159265358979323846 / 180.0);
  }
  /// Sign applied to steering angles (and yaw rates).
  [[nodiscard]] double turnSign() const { return mirror ? -1.0 : 1.0; }
  /// The input that drives the image scene like `in` drives the original.
  [[nodiscard]] InputFrame input(const InputFrame& in) const {
    if (!mirror) return in;
    return {in.up, in.down, in.right, in.left};
  }
  /// Short description for failure messages.
  [[nodiscard]] std::string describe() const {
    char buf[128];
    std::snprintf(buf, sizeof buf, "translate (%.17g, %.17g), rotate %.17g deg%s", translate.x(),
                  translate.y(), rotate_deg, mirror ? ", mirror y" : "");
    return buf;
  }
};

/// The scene moved by `t`. Bounds are kept when the rotation keeps axes (they map exactly onto an
/// axis-aligned box); otherwise they are dropped, since walls are axis-aligned by the format: the
/// caller compares against the original without bounds (`withoutBounds`).
inline Scene transformed(const Scene& s, const RigidTransform& t) {
  Scene out = s;
  out.player.position = t.point(s.player.position);
  out.player.heading_deg = t.headingDeg(s.player.heading_deg);
  for (ParkedCar& p : out.parked) {
    p.heading_deg = t.headingDeg(p.heading_deg);
    p.box = Obb2::fromDegrees(t.point(p.box.center), p.heading_deg, 2.0 * p.box.half.x(),
                              2.0 * p.box.half.y());
  }
  for (Obstacle& o : out.obstacles) {
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < o.polygon.count; ++i) points.push_back(t.point(o.polygon.vertex(i)));
    o.polygon = *ConvexPolygon::fromPoints(points);
  }
  if (s.bounds && t.keepsAxes()) {
    const Eigen::Vector2d a = t.point(s.bounds->min), b = t.point(s.bounds->max);
    out.bounds = Aabb2{a.cwiseMin(b), a.cwiseMax(b)};
  } else {
    out.bounds.reset();
  }
  return out;
}

/// The scene with its walls removed.
inline Scene withoutBounds(Scene s) {
  s.bounds.reset();
  return s;
}

}  // namespace cardemo::stress
