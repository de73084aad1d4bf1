#include "render/headlights.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace cardemo {
namespace {

// Slices per beam: each slice's two edge rays are cut at what they meet, so a car or a wall
// across part of a beam shadows that part only.
constexpr int kSlices = 8;
constexpr int kBeamAlpha = 20;

// A ray from `from` along `along` (t in 0..1 spans its length).
struct Ray {
  Eigen::Vector2d from;
  Eigen::Vector2d along;
};

// First t in [0, 1] at which the ray is inside the convex polygon `poly` (either winding), or 1
// when it never is (Cyrus and Beck 1978: clip the ray by each edge's half-plane).
double hitConvex(const Ray& ray, std::span<const Eigen::Vector2d> poly) {
  const std::size_t n = poly.size();
  double area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = poly[i] - ray.from;
    const Eigen::Vector2d b = poly[(i + 1) % n] - ray.from;
    area += a.x() * b.y() - a.y() * b.x();
  }
  const double outward = area >= 0.0 ? 1.0 : -1.0;
  double enter = 0.0;
  double leave = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    // Relative to the ray's start first, so a lot far from the origin loses nothing.
    const Eigen::Vector2d a = poly[i] - ray.from;
    const Eigen::Vector2d e = poly[(i + 1) % n] - poly[i];
    const Eigen::Vector2d normal = outward * Eigen::Vector2d{e.y(), -e.x()};
    const double num = normal.dot(a);  // > 0: the start is inside this edge
    const double den = normal.dot(ray.along);
    if (den == 0.0) {
      if (num < 0.0) return 1.0;
      continue;
    }
    const double t = num / den;
    if (den < 0.0) {
      enter = std::max(enter, t);
    } else {
      leave = std::min(leave, t);
    }
    if (enter > leave) return 1.0;
  }
  return enter;
}

// Last t in [0, 1] at which the ray is still inside the lot's walls.
double insideBounds(const Ray& ray, const Aabb2& bounds) {
  double t = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double v = ray.along[axis];
    const double p = ray.from[axis];
    if (p < bounds.min[axis] || p > bounds.max[axis]) return 0.0;
    if (v > 0.0) t = std::min(t, (bounds.max[axis] - p) / v);
    if (v < 0.0) t = std::min(t, (bounds.min[axis] - p) / v);
  }
  return std::max(0.0, t);
}

// What can stop a beam: the parked cars and obstacles near it, and the walls.
struct Occluders {
  const Aabb2* bounds = nullptr;
  std::vector<std::array<Eigen::Vector2d, 4>> boxes;
  std::vector<const ConvexPolygon*> polygons;
};

Occluders occludersNear(const World& world, const Aabb2& lit) {
  const Scene& scene = world.scene();
  Occluders o;
  if (scene.bounds) o.bounds = &*scene.bounds;
  // The World's collider bounds are built once (parked cars first, then obstacles), so a frame
  // only compares boxes here rather than recomputing every car's bounds.
  const StaticColliders& colliders = world.colliders();
  const std::size_t parked = scene.parked.size();
  for (std::size_t i = 0; i < parked; ++i) {
    if (colliders.bounds(static_cast<std::uint32_t>(i)).overlaps(lit)) {
      o.boxes.push_back(scene.parked[i].box.corners());
    }
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (colliders.bounds(static_cast<std::uint32_t>(parked + i)).overlaps(lit)) {
      o.polygons.push_back(&scene.obstacles[i].polygon);
    }
  }
  return o;
}

// How far along the ray (0..1) the light gets.
double reach(const Ray& ray, const Occluders& o) {
  double t = o.bounds != nullptr ? insideBounds(ray, *o.bounds) : 1.0;
  for (const auto& corners : o.boxes) t = std::min(t, hitConvex(ray, corners));
  for (const ConvexPolygon* p : o.polygons) {
    t = std::min(t, hitConvex(ray, std::span<const Eigen::Vector2d>(
                                       p->vertices.data(), static_cast<std::size_t>(p->count))));
  }
  return t;
}

}  // namespace

void drawHeadlightBeams(Canvas& canvas, const Camera& camera, const World& world, const Obb2& box,
                        const Palette& palette) {
  const double hx = box.half.x();
  const double hy = box.half.y();
  const auto at = [&box](double lx, double ly) -> Eigen::Vector2d {
    return box.center + box.axis * lx + box.perp() * ly;
  };
  const double far = hx + kBeamLengthM;
  const Eigen::Vector2d reach_half{0.5 * kBeamLengthM, hy + 1.0};
  const Aabb2 lit = Obb2{at(hx + 0.5 * kBeamLengthM, 0.0), box.axis, reach_half}.aabb();
  const Occluders occluders = occludersNear(world, lit);
  Rgba beam = palette.headlight;
  beam.a = kBeamAlpha;
  for (const double side : {1.0, -1.0}) {
    // From the lamp (0.55 to 0.85 of the half width) to a wider patch kBeamLengthM ahead.
    const Eigen::Vector2d near_a = at(hx, side * 0.55 * hy);
    const Eigen::Vector2d near_b = at(hx, side * 0.85 * hy);
    const Eigen::Vector2d far_a = at(far, side * (0.55 * hy - 0.6));
    const Eigen::Vector2d far_b = at(far, side * (0.85 * hy + 0.8));
    std::array<Eigen::Vector2d, kSlices + 1> from;
    std::array<Eigen::Vector2d, kSlices + 1> to;
    for (int i = 0; i <= kSlices; ++i) {
      const double u = static_cast<double>(i) / kSlices;
      const Ray ray{near_a + (near_b - near_a) * u,
                    far_a + (far_b - far_a) * u - (near_a + (near_b - near_a) * u)};
      const auto k = static_cast<std::size_t>(i);
      from[k] = ray.from;
      to[k] = ray.from + ray.along * reach(ray, occluders);
    }
    for (std::size_t i = 0; i < kSlices; ++i) {
      if (to[i] == from[i] && to[i + 1] == from[i + 1]) continue;  // blocked at the bumper
      const std::array<Eigen::Vector2f, 4> slice{
          camera.toScreen(from[i]), camera.toScreen(from[i + 1]), camera.toScreen(to[i + 1]),
          camera.toScreen(to[i])};
      canvas.fillConvex(slice, beam);
    }
  }
}

}  // namespace cardemo
