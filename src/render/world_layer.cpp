#include "render/world_layer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <variant>

#include "render/car_art.hpp"
#include "render/effects_layer.hpp"
#include "render/gate_marks.hpp"
#include "render/goal_overlay.hpp"
#include "render/ground_layer.hpp"
#include "render/headlights.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

// Lines closer than this many pixels are not drawn (they would just tint the ground).
constexpr double kMinGridSpacingPx = 6.0;
// Beyond this many lines per axis the grid is skipped (a guard, not a normal case).
constexpr double kMaxGridLines = 4000.0;
// Past 2^52 consecutive integers are no longer representable, so k += step would stall.
constexpr double kMaxGridCoordinate = 1e15;

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

void drawObstacle(Canvas& canvas, const Camera& camera, const ConvexPolygon& poly,
                  const Palette& palette) {
  std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices> pts;
  for (int i = 0; i < poly.count; ++i)
    pts[static_cast<std::size_t>(i)] = camera.toScreen(poly.vertex(i));
  const std::span<const Eigen::Vector2f> span(pts.data(), static_cast<std::size_t>(poly.count));
  const Aabb2 bounds = poly.aabb();
  if ((bounds.max - bounds.min).maxCoeff() > kPostMaxSize) {
    canvas.fillConvex(span, palette.obstacle);
    outline(canvas, span, 2.0f, shade(palette.obstacle, 0.7));
    return;
  }
  // A post or pillar: small enough to miss at a glance, so painted, with a lighter cap.
  canvas.fillConvex(span, palette.post);
  outline(canvas, span, 2.0f, shade(palette.post, 0.45));
  Eigen::Vector2f centre = Eigen::Vector2f::Zero();
  for (const Eigen::Vector2f& p : span) centre += p;
  centre /= static_cast<float>(span.size());
  std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices> cap;
  for (std::size_t i = 0; i < span.size(); ++i) cap[i] = centre + 0.5f * (span[i] - centre);
  canvas.fillConvex(std::span<const Eigen::Vector2f>(cap.data(), span.size()),
                    shade(palette.post, 1.2));
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

void drawWorldLayer(Canvas& canvas, const World& world, const Camera& camera,
                    const Obb2& player_box, const DrawOptions& options, const Palette& palette) {
  const Scene& scene = world.scene();
  const Aabb2 view = visibleWorld(camera);
  const Effects* fx = options.effects;
  drawGround(canvas, camera, scene, palette, options.sprites);
  if (options.debug_overlay) {
    drawGroundGrid(canvas, camera, palette, scene.bounds ? &*scene.bounds : nullptr);
  }
  // A scene that paints its own lines gets no automatic bays.
  if (scene.markings.empty()) drawBayLines(canvas, camera, scene, palette);
  drawMarkings(canvas, camera, scene, palette);
  // Paint on the ground, so the cars drive over it.
  if (options.goal != nullptr) {
    // A level's bay is painted with the scene's markings; the chain's moves from bay to bay.
    if (options.goal->chain != nullptr && !options.goal->chain->over()) {
      drawGoalPaint(canvas, camera, options.goal->challenge->goal().bay, palette);
    }
    drawGoalBay(canvas, camera, *options.goal);
    drawGates(canvas, camera, *options.goal->challenge);
  }
  if (fx != nullptr) drawSkidMarks(canvas, camera, *fx, palette);
  // Light on the ground: under the walls and the cars, which would otherwise be painted over.
  drawHeadlightBeams(canvas, camera, world, player_box, palette);
  if (scene.bounds) drawWalls(canvas, camera, *scene.bounds, palette);
  for (const Obstacle& o : scene.obstacles) {
    if (o.polygon.aabb().overlaps(view)) drawObstacle(canvas, camera, o.polygon, palette);
  }
  const std::span<const Dent> dents =
      fx != nullptr ? std::span<const Dent>(fx->dents()) : std::span<const Dent>();
  const double wheelbase = world.settings().car.wheelbase;
  for (std::size_t i = 0; i < scene.parked.size(); ++i) {
    const ParkedCar& car = scene.parked[i];
    if (!car.box.aabb().overlaps(view)) continue;
    CarLook look;
    look.body = parkedColor(car.id, palette);
    look.wheelbase = wheelbase;
    look.dents = dents;
    look.owner = static_cast<std::uint32_t>(i);
    if (fx != nullptr) look.flash = fx->colliderFlash(static_cast<std::uint32_t>(i));
    drawCarArt(canvas, camera, car.box, look, palette, options.sprites);
  }
  CarLook player;
  player.body = palette.player;
  player.steer = world.car().steer;
  player.wheelbase = wheelbase;
  player.lit = true;
  player.dents = dents;
  const int max_health = scene.player.health;
  player.damage = max_health > 0 ? 1.0 - std::clamp(world.health(), 0, max_health) /
                                             static_cast<double>(max_health)
                                 : 0.0;
  if (fx != nullptr) {
    player.braking = fx->braking();
    player.reversing = fx->reversing();
    player.flash = fx->playerFlash();
  } else {
    player.reversing = world.car().speed < -0.05;
  }
  drawCarArt(canvas, camera, player_box, player, palette, options.sprites);
}

}  // namespace cardemo
