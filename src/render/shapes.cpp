#include "render/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace cardemo {

std::array<Eigen::Vector2f, 4> projectObb(const Camera& camera, const Obb2& box) {
  const std::array<Eigen::Vector2d, 4> c = box.corners();
  return {camera.toScreen(c[0]), camera.toScreen(c[1]), camera.toScreen(c[2]),
          camera.toScreen(c[3])};
}

std::pair<Eigen::Vector2f, Eigen::Vector2f> screenRect(const Camera& camera, const Obb2& box) {
  Eigen::Vector2f lo{1e30f, 1e30f};
  Eigen::Vector2f hi{-1e30f, -1e30f};
  for (const Eigen::Vector2f& p : projectObb(camera, box)) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

std::array<Eigen::Vector2f, 4> windscreenQuad(const Camera& camera, const Obb2& box) {
  const Eigen::Vector2d a = box.axis;
  const Eigen::Vector2d p = box.perp();
  const double hx = box.half.x();
  const double hy = box.half.y();
  // Offsets are taken from the centre in double, so the quad is exact far from the origin.
  auto at = [&](double lx, double ly) { return camera.toScreen(box.center + a * lx + p * ly); };
  return {at(0.12 * hx, -0.82 * hy), at(0.5 * hx, -0.7 * hy), at(0.5 * hx, 0.7 * hy),
          at(0.12 * hx, 0.82 * hy)};
}

Aabb2 visibleWorld(const Camera& camera) {
  const double margin = 2.0 / camera.pixels_per_metre;
  const Eigen::Vector2d lo = camera.toWorld({0.0f, static_cast<float>(camera.viewport.y())});
  const Eigen::Vector2d hi = camera.toWorld({static_cast<float>(camera.viewport.x()), 0.0f});
  return {lo.array() - margin, hi.array() + margin};
}

void outline(Canvas& canvas, std::span<const Eigen::Vector2f> points, float thickness,
             const Rgba& color) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    canvas.line(points[i], points[(i + 1) % points.size()], thickness, color);
  }
}

void arrow(Canvas& canvas, const Eigen::Vector2f& from, const Eigen::Vector2f& to, float thickness,
           float head, const Rgba& color) {
  canvas.line(from, to, thickness, color);
  const Eigen::Vector2f d = to - from;
  const float len = d.norm();
  if (len < 1e-3f) return;
  const Eigen::Vector2f u = d / len;
  const Eigen::Vector2f n{-u.y(), u.x()};
  const float h = std::min(head, 0.6f * len);
  const std::array<Eigen::Vector2f, 3> tip{to, to - u * h + n * (0.5f * h),
                                           to - u * h - n * (0.5f * h)};
  canvas.fillConvex(tip, color);
}

void fillRect(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
              const Rgba& color) {
  const std::array<Eigen::Vector2f, 4> quad{
      top_left, Eigen::Vector2f{top_left.x() + size.x(), top_left.y()}, top_left + size,
      Eigen::Vector2f{top_left.x(), top_left.y() + size.y()}};
  canvas.fillConvex(quad, color);
}

Rgba shade(const Rgba& color, double factor) {
  auto ch = [factor](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v * factor), 0L, 255L));
  };
  return {ch(color.r), ch(color.g), ch(color.b), color.a};
}

}  // namespace cardemo
