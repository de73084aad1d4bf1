#include "render/world_layer.hpp"

#include <array>
#include <cmath>
#include <variant>

#include "render/shapes.hpp"

namespace cardemo {
namespace {

// Lines closer than this many pixels are not drawn (they would just tint the ground).
constexpr double kMinGridSpacingPx = 6.0;
// Beyond this many lines per axis the grid is skipped (a guard, not a normal case).
constexpr double kMaxGridLines = 4000.0;
// Past 2^52 consecutive integers are no longer representable, so k += step would stall.
constexpr double kMaxGridCoordinate = 1e15;
constexpr double kWallThicknessM = 0.6;

void gridLines(Canvas& canvas, const Camera& camera, const Aabb2& view, double step, float px,
               const Rgba& color, bool skip_major) {
  // Each line spans the view: the screen, or less when the view is clipped to the walls.
  const Eigen::Vector2f lo_px = camera.toScreen(view.min);  // bottom-left on screen
  const Eigen::Vector2f hi_px = camera.toScreen(view.max);  // top-right on screen
  for (int axis = 0; axis < 2; ++axis) {
    const double first = std::ceil(view.min[axis] / step);
    const double lo = first * step;
    const double hi = view.max[axis];
    if (!((hi - lo) / step <= kMaxGridLines)) continue;  // also skips NaN
    // An integer counter: adding `step` to a double would drift, and far out could stop advancing.
    const int lines = static_cast<int>(std::floor(hi / step) - first);
    for (int i = 0; i <= lines; ++i) {
      const double k = (first + i) * step;
      if (skip_major && std::fmod(k, 10.0) == 0.0) continue;
      Eigen::Vector2d w = camera.center;
      w[axis] = k;
      const Eigen::Vector2f s = camera.toScreen(w);
      if (axis == 0) {
        canvas.line({s.x(), hi_px.y()}, {s.x(), lo_px.y()}, px, color);
      } else {
        canvas.line({lo_px.x(), s.y()}, {hi_px.x(), s.y()}, px, color);
      }
    }
  }
}

void drawWalls(Canvas& canvas, const Camera& camera, const Aabb2& b, const Palette& palette) {
  const double t = kWallThicknessM;
  const std::array<Aabb2, 4> walls{
      Aabb2{{b.min.x() - t, b.min.y() - t}, {b.max.x() + t, b.min.y()}},
      Aabb2{{b.min.x() - t, b.max.y()}, {b.max.x() + t, b.max.y() + t}},
      Aabb2{{b.min.x() - t, b.min.y()}, {b.min.x(), b.max.y()}},
      Aabb2{{b.max.x(), b.min.y()}, {b.max.x() + t, b.max.y()}}};
  const Aabb2 view = visibleWorld(camera);
  for (const Aabb2& w : walls) {
    if (!w.overlaps(view)) continue;
    const std::array<Eigen::Vector2f, 4> quad{
        camera.toScreen(w.min), camera.toScreen({w.max.x(), w.min.y()}), camera.toScreen(w.max),
        camera.toScreen({w.min.x(), w.max.y()})};
    canvas.fillConvex(quad, palette.wall);
  }
}

void drawObstacle(Canvas& canvas, const Camera& camera, const ConvexPolygon& poly,
                  const Palette& palette) {
  std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices> pts;
  for (int i = 0; i < poly.count; ++i)
    pts[static_cast<std::size_t>(i)] = camera.toScreen(poly.vertex(i));
  const std::span<const Eigen::Vector2f> span(pts.data(), static_cast<std::size_t>(poly.count));
  canvas.fillConvex(span, palette.obstacle);
  outline(canvas, span, 2.0f, shade(palette.obstacle, 0.7));
}

}  // namespace

void drawGroundGrid(Canvas& canvas, const Camera& camera, const Palette& palette,
                    const Aabb2* clip) {
  Aabb2 view = visibleWorld(camera);
  if (clip != nullptr) {
    if (!clip->overlaps(view)) return;
    view = {view.min.cwiseMax(clip->min), view.max.cwiseMin(clip->max)};
  }
  const double ppm = camera.pixels_per_metre;
  if (!(ppm > 0.0) || view.min.cwiseAbs().maxCoeff() > kMaxGridCoordinate ||
      view.max.cwiseAbs().maxCoeff() > kMaxGridCoordinate) {
    return;
  }
  if (ppm * 1.0 >= kMinGridSpacingPx)
    gridLines(canvas, camera, view, 1.0, 1.0f, palette.grid, true);
  if (ppm * 10.0 >= kMinGridSpacingPx) {
    gridLines(canvas, camera, view, 10.0, 2.0f, shade(palette.grid, 1.35), false);
  }
}

void drawCar(Canvas& canvas, const Camera& camera, const Obb2& box, const Rgba& body,
             const Palette& palette) {
  const std::array<Eigen::Vector2f, 4> corners = projectObb(camera, box);
  canvas.fillConvex(corners, body);
  outline(canvas, corners, 1.5f, shade(body, 0.6));
  canvas.fillConvex(windscreenQuad(camera, box), palette.windscreen);
}

void drawWorldLayer(Canvas& canvas, const World& world, const Camera& camera,
                    const Obb2& player_box, const Palette& palette) {
  const Scene& scene = world.scene();
  const Aabb2 view = visibleWorld(camera);
  if (scene.bounds) {
    // The lot itself in the ground colour; drawFrame cleared the screen to `outside`.
    const Aabb2& b = *scene.bounds;
    const std::array<Eigen::Vector2f, 4> lot{
        camera.toScreen(b.min), camera.toScreen({b.max.x(), b.min.y()}), camera.toScreen(b.max),
        camera.toScreen({b.min.x(), b.max.y()})};
    canvas.fillConvex(lot, palette.ground);
  }
  drawGroundGrid(canvas, camera, palette, scene.bounds ? &*scene.bounds : nullptr);
  if (scene.bounds) drawWalls(canvas, camera, *scene.bounds, palette);
  for (const Obstacle& o : scene.obstacles) {
    if (o.polygon.aabb().overlaps(view)) drawObstacle(canvas, camera, o.polygon, palette);
  }
  for (const ParkedCar& car : scene.parked) {
    if (car.box.aabb().overlaps(view)) drawCar(canvas, camera, car.box, palette.parked, palette);
  }
  drawCar(canvas, camera, player_box, palette.player, palette);
}

}  // namespace cardemo
