#include "render/debug_overlay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "render/hud.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

// Outline points of a box or polygon in pixels; returns how many are used.
int shapePoints(const Camera& camera, const Obb2& box,
                std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices>& out) {
  const auto c = projectObb(camera, box);
  std::copy(c.begin(), c.end(), out.begin());
  return 4;
}

int shapePoints(const Camera& camera, const ConvexPolygon& poly,
                std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices>& out) {
  for (int i = 0; i < poly.count; ++i) {
    out[static_cast<std::size_t>(i)] = camera.toScreen(poly.vertex(i));
  }
  return poly.count;
}

// Outline points of collider i in pixels; returns how many are used.
int colliderPoints(const Camera& camera, const StaticColliders& colliders, std::uint32_t i,
                   std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices>& out) {
  return colliders.visit(i, [&](const auto& shape) { return shapePoints(camera, shape, out); });
}

// Support distance of the box along unit direction n (half its width along n).
double supportDistance(const Obb2& box, const Eigen::Vector2d& n) {
  return std::abs(n.dot(box.axis)) * box.half.x() + std::abs(n.dot(box.perp())) * box.half.y();
}

void drawCounters(Canvas& canvas, const World& world, const OverlayPalette& palette) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const int h = static_cast<int>(std::lround(14.0f * s));
  const WorldStats& st = world.stats();
  const Rgba white{235, 238, 242, 255};
  const std::vector<HudRow> rows{
      {"DEBUG OVERLAY (B)", "", {255, 220, 90, 255}},
      {"candidates", std::to_string(world.candidates().size()), palette.candidate},
      {"contacts", std::to_string(world.contacts().size()), palette.normal},
      {"colliders", std::to_string(world.colliders().size()), white},
      {"queries run", std::to_string(st.broadphase_queries), white},
      {"queries reused", std::to_string(st.reused_queries), white},
      {"queries skipped", std::to_string(st.skipped_queries), white},
      {"candidates, total", std::to_string(st.broadphase_candidates), white},
      {"narrow-phase tests", std::to_string(st.narrowphase_tests), white},
      {"sub-steps", std::to_string(st.substeps), white},
  };
  const float pad = 10.0f * s;
  const float w = tableWidth(canvas, rows, h);
  const float row = h * 1.3f;
  const Eigen::Vector2f tl{static_cast<float>(vp.x()) - w - 2.0f * pad - 12.0f * s, 12.0f * s};
  fillRect(canvas, tl, {w + 2.0f * pad, row * static_cast<float>(rows.size()) + 1.5f * pad},
           {12, 14, 18, 190});
  drawTable(canvas, tl + Eigen::Vector2f{pad, pad}, w, rows, h);
}

}  // namespace

Aabb2 broadPhaseBox(const World& world) {
  const Obb2 box = world.carBox();
  return queryBox(box, box.aabb(), world.settings().schemes);
}

void drawDebugOverlay(Canvas& canvas, const World& world, const Camera& camera,
                      const OverlayPalette& palette) {
  const Aabb2 view = visibleWorld(camera);
  std::array<Eigen::Vector2f, ConvexPolygon::kMaxVertices> pts;
  const auto span = [&pts](int n) {
    return std::span<const Eigen::Vector2f>(pts.data(), static_cast<std::size_t>(n));
  };

  Rgba candidate_fill = palette.candidate;
  candidate_fill.a = 70;
  const StaticColliders& colliders = world.colliders();
  for (std::uint32_t i : world.candidates()) {
    if (i >= colliders.size()) continue;
    canvas.fillConvex(span(colliderPoints(camera, colliders, i, pts)), candidate_fill);
  }
  for (std::uint32_t i = 0; i < colliders.size(); ++i) {
    if (!colliders.bounds(i).overlaps(view)) continue;
    outline(canvas, span(colliderPoints(camera, colliders, i, pts)), 1.5f, palette.obb);
  }
  for (std::uint32_t i : world.candidates()) {
    if (i >= colliders.size()) continue;
    outline(canvas, span(colliderPoints(camera, colliders, i, pts)), 3.0f, palette.candidate);
  }

  const Obb2 player = world.carBox();
  const auto corners = projectObb(camera, player);
  outline(canvas, corners, 2.0f, palette.obb);
  const Aabb2 b = broadPhaseBox(world);
  const std::array<Eigen::Vector2f, 4> aabb{
      camera.toScreen(b.min), camera.toScreen({b.max.x(), b.min.y()}), camera.toScreen(b.max),
      camera.toScreen({b.min.x(), b.max.y()})};
  outline(canvas, aabb, 2.0f, palette.aabb);

  const float head = 10.0f;
  for (const ActiveContact& c : world.contacts()) {
    const Eigen::Vector2d n = c.normal;
    // Both arrows start on the player's boundary in the normal's direction: the normal points into
    // the collider, the minimum translation pushes the player back out.
    const Eigen::Vector2d base = player.center + n * supportDistance(player, n);
    const double normal_len = std::max(1.5, 30.0 / camera.pixels_per_metre);
    arrow(canvas, camera.toScreen(base), camera.toScreen(base + n * normal_len), 2.5f, head,
          palette.normal);
    const double depth = std::max(0.0, -c.separation);
    const double mtv_len = std::max(depth * kMtvScale, 12.0 / camera.pixels_per_metre);
    arrow(canvas, camera.toScreen(base), camera.toScreen(base - n * mtv_len), 2.5f, head,
          palette.mtv);
  }
  drawCounters(canvas, world, palette);
}

}  // namespace cardemo
