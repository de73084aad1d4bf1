#include "render/ground_layer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "render/shapes.hpp"
#include "render/world_layer.hpp"

namespace cardemo {
namespace {

constexpr double kPatchCellM = 5.0;
constexpr double kTileM = 6.0;
constexpr double kMinTilePx = 40.0;
constexpr double kKerbBlockM = 1.5;
constexpr double kBayHalfWidthM = 1.3;
constexpr double kLineWidthM = 0.12;
// Beyond this many cells or tiles in view the texture is left out (a guard for extreme zooms).
constexpr double kMaxCells = 6000.0;

std::uint64_t cellHash(std::int64_t x, std::int64_t y) {
  // splitmix64 (Steele, Lea, Flood 2014) over both coordinates.
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ull ^
                    (static_cast<std::uint64_t>(y) + 0x632be59bd9b4e019ull);
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

std::array<Eigen::Vector2f, 4> rect(const Camera& camera, const Aabb2& b) {
  return {camera.toScreen(b.min), camera.toScreen({b.max.x(), b.min.y()}), camera.toScreen(b.max),
          camera.toScreen({b.min.x(), b.max.y()})};
}

// The part of the view the ground covers (the lot, or all of it without walls); false if none.
bool groundArea(const Camera& camera, const Scene& scene, Aabb2& area) {
  area = visibleWorld(camera);
  if (!scene.bounds) return true;
  if (!scene.bounds->overlaps(area)) return false;
  area = {area.min.cwiseMax(scene.bounds->min), area.max.cwiseMin(scene.bounds->max)};
  return true;
}

// True when the cells [lo, hi] (whole numbers, both axes) are at least one and at most
// kMaxCells: false for an empty, NaN or huge range, so the loops over them stay short.
bool fewCells(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const Eigen::Vector2d n = hi - lo + Eigen::Vector2d::Ones();
  return n.x() >= 1.0 && n.y() >= 1.0 && n.x() * n.y() <= kMaxCells;
}

void drawPatches(Canvas& canvas, const Camera& camera, const Aabb2& area, const Aabb2* lot,
                 const Palette& palette) {
  const Eigen::Vector2d lo = (area.min / kPatchCellM).array().floor();
  const Eigen::Vector2d hi = (area.max / kPatchCellM).array().floor();
  if (!fewCells(lo, hi)) return;
  if (camera.pixels_per_metre * kPatchCellM < 6.0) return;
  constexpr int kSides = 8;
  std::array<Eigen::Vector2f, kSides> pts;
  for (auto cy = static_cast<std::int64_t>(lo.y()); cy <= static_cast<std::int64_t>(hi.y()); ++cy) {
    for (auto cx = static_cast<std::int64_t>(lo.x()); cx <= static_cast<std::int64_t>(hi.x());
         ++cx) {
      const std::uint64_t h = cellHash(cx, cy);
      if (h % 3 != 0) continue;  // one cell in three gets a stain
      const double u = static_cast<double>((h >> 8) & 0xff) / 255.0;
      const double v = static_cast<double>((h >> 16) & 0xff) / 255.0;
      const double rx = 0.8 + 1.6 * static_cast<double>((h >> 24) & 0xff) / 255.0;
      const double ry = 0.5 + 1.0 * static_cast<double>((h >> 32) & 0xff) / 255.0;
      const Eigen::Vector2d c{(static_cast<double>(cx) + u) * kPatchCellM,
                              (static_cast<double>(cy) + v) * kPatchCellM};
      const Aabb2 extent{c.array() - rx, c.array() + rx};
      if (!extent.overlaps(area)) continue;
      // Stains stay off the walls.
      if (lot != nullptr && !(extent.min.cwiseMax(lot->min) == extent.min &&
                              extent.max.cwiseMin(lot->max) == extent.max)) {
        continue;
      }
      const double ang = static_cast<double>((h >> 40) & 0xff) / 255.0 * std::numbers::pi;
      const Eigen::Vector2d ax{std::cos(ang), std::sin(ang)};
      const Eigen::Vector2d ay{-ax.y(), ax.x()};
      // An irregular octagon: a worn patch or an oil stain rather than a tile.
      for (int i = 0; i < kSides; ++i) {
        const double t = 2.0 * std::numbers::pi * i / kSides;
        const double k = 0.8 + 0.2 * static_cast<double>((h >> (i * 3)) & 7) / 7.0;
        pts[static_cast<std::size_t>(i)] =
            camera.toScreen(c + ax * (std::cos(t) * rx * k) + ay * (std::sin(t) * ry * k));
      }
      canvas.fillConvex(pts, (h >> 48) % 3 == 0 ? palette.asphalt_light : palette.asphalt_dark);
    }
  }
}

void drawTiles(Canvas& canvas, const Camera& camera, const Scene& scene, const Aabb2& area) {
  double tile = kTileM;
  while (tile * camera.pixels_per_metre < kMinTilePx) tile *= 2.0;
  // Tiles start at the lot's corner (or the origin), so they stay put as the camera moves.
  const Eigen::Vector2d origin = scene.bounds ? scene.bounds->min : Eigen::Vector2d::Zero();
  const Eigen::Vector2d lo = ((area.min - origin) / tile).array().floor();
  const Eigen::Vector2d hi = ((area.max - origin) / tile).array().floor();
  if (!fewCells(lo, hi)) return;
  // One pixel of overlap hides the seams between tiles.
  const auto px = static_cast<float>(tile * camera.pixels_per_metre + 1.0);
  const auto columns = static_cast<int>(hi.x() - lo.x()), rows = static_cast<int>(hi.y() - lo.y());
  for (int row = 0; row <= rows; ++row) {
    for (int column = 0; column <= columns; ++column) {
      const Eigen::Vector2d c =
          origin + Eigen::Vector2d{lo.x() + column + 0.5, lo.y() + row + 0.5} * tile;
      canvas.image(ImageId::kGround, camera.toScreen(c), 0.0f, {px, px}, {255, 255, 255, 255});
    }
  }
}

}  // namespace

void drawGround(Canvas& canvas, const Camera& camera, const Scene& scene, const Palette& palette,
                bool sprites) {
  if (scene.bounds) canvas.fillConvex(rect(camera, *scene.bounds), palette.ground);
  Aabb2 area;
  if (!groundArea(camera, scene, area)) return;
  if (sprites && canvas.hasImage(ImageId::kGround)) {
    drawTiles(canvas, camera, scene, area);
    if (scene.bounds) {
      // Tiles overhang the lot's far sides: cover the overhang with the ground outside.
      const Aabb2 view = visibleWorld(camera);
      const Aabb2& b = *scene.bounds;
      const double far = kTileM * 64.0;
      for (const Aabb2& o :
           {Aabb2{{b.max.x(), b.min.y() - far}, {b.max.x() + far, b.max.y() + far}},
            Aabb2{{b.min.x() - far, b.max.y()}, {b.max.x(), b.max.y() + far}}}) {
        if (o.overlaps(view)) canvas.fillConvex(rect(camera, o), palette.outside);
      }
    }
  } else {
    drawPatches(canvas, camera, area, scene.bounds ? &*scene.bounds : nullptr, palette);
  }
}

void drawBayLines(Canvas& canvas, const Camera& camera, const Scene& scene,
                  const Palette& palette) {
  const Aabb2 view = visibleWorld(camera);
  const float w = std::max(1.0f, static_cast<float>(kLineWidthM * camera.pixels_per_metre));
  for (const ParkedCar& car : scene.parked) {
    const Obb2& b = car.box;
    if (!b.aabb().overlaps(view)) continue;
    const double hy = std::max(kBayHalfWidthM, b.half.y() + 0.35);
    const double hx = b.half.x() + 0.45;
    auto at = [&b, &camera](double x, double y) {
      return camera.toScreen(b.center + b.axis * x + b.perp() * y);
    };
    canvas.line(at(-hx, hy), at(hx, hy), w, palette.bay_line);
    canvas.line(at(-hx, -hy), at(hx, -hy), w, palette.bay_line);
    canvas.line(at(-hx, -hy), at(-hx, hy), w, palette.bay_line);
  }
}

void drawMarkings(Canvas& canvas, const Camera& camera, const Scene& scene,
                  const Palette& palette) {
  const Aabb2 view = visibleWorld(camera);
  const double ppm = camera.pixels_per_metre;
  for (const Marking& m : scene.markings) {
    const Aabb2 b{m.from.cwiseMin(m.to).array() - 1.0, m.from.cwiseMax(m.to).array() + 1.0};
    if (!b.overlaps(view)) continue;
    const float w = std::max(1.0f, static_cast<float>(m.width * ppm));
    if (m.kind == Marking::Kind::kLine) {
      canvas.line(camera.toScreen(m.from), camera.toScreen(m.to), w, palette.paint);
    } else {
      const double len = (m.to - m.from).norm();
      arrow(canvas, camera.toScreen(m.from), camera.toScreen(m.to), w,
            static_cast<float>(std::min(1.2, 0.45 * len) * ppm), palette.paint);
    }
  }
  if (!scene.goal) return;
  // Every bay of the goal; in a chain each is numbered in its order instead of a "P".
  const Goal& goal = *scene.goal;
  const std::size_t count = 1 + goal.next_bays.size();
  for (std::size_t i = 0; i < count; ++i) {
    const ParkingBay& bay = i == 0 ? goal.bay : goal.next_bays[i - 1];
    drawGoalPaint(canvas, camera, bay, palette, count > 1 ? std::to_string(i + 1) : "P");
  }
}

void drawGoalPaint(Canvas& canvas, const Camera& camera, const ParkingBay& bay,
                   const Palette& palette, const std::string& mark) {
  const double ppm = camera.pixels_per_metre;
  const Obb2 box = Obb2::fromDegrees(bay.center, bay.heading_deg, bay.length, bay.width);
  if (!box.aabb().overlaps(visibleWorld(camera))) return;
  const auto corners = projectObb(camera, box);
  Rgba fill = palette.goal_bay;
  fill.a = 45;
  canvas.fillConvex(corners, fill);
  outline(canvas, corners, std::max(2.0f, static_cast<float>(0.15 * ppm)), palette.goal_bay);
  // A "P" (or the bay's number in a chain) painted in the bay.
  const int px = static_cast<int>(std::lround(std::min(bay.length, bay.width) * 0.55 * ppm));
  if (px >= 8) {
    const Eigen::Vector2f size = canvas.textSize(mark, px);
    canvas.text(camera.toScreen(bay.center) - 0.5f * size, mark, px, palette.goal_bay);
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
    if (w.overlaps(view)) canvas.fillConvex(rect(camera, w), palette.wall);
  }
  if (camera.pixels_per_metre * kKerbBlockM < 6.0) return;
  // Kerb blocks on the inner half of each wall, counted from the lot's corner so they stay put.
  const double k = 0.5 * t;
  for (int side = 0; side < 4; ++side) {
    const bool horizontal = side < 2;
    const int axis = horizontal ? 0 : 1;
    const double lo = std::max(b.min[axis], view.min[axis]);
    const double hi = std::min(b.max[axis], view.max[axis]);
    if (!(lo < hi)) continue;
    const double y0 = side == 0 ? b.min.y() - k : side == 1 ? b.max.y() : 0.0;
    const double x0 = side == 2 ? b.min.x() - k : side == 3 ? b.max.x() : 0.0;
    const Aabb2 band = horizontal ? Aabb2{{lo, y0}, {hi, y0 + k}} : Aabb2{{x0, lo}, {x0 + k, hi}};
    if (!band.overlaps(view)) continue;
    const auto first = static_cast<std::int64_t>(std::floor((lo - b.min[axis]) / kKerbBlockM));
    const auto last = static_cast<std::int64_t>(std::floor((hi - b.min[axis]) / kKerbBlockM));
    if (last - first > 4000) continue;
    for (std::int64_t i = first; i <= last; ++i) {
      const double s = std::max(lo, b.min[axis] + static_cast<double>(i) * kKerbBlockM);
      const double e = std::min(hi, b.min[axis] + static_cast<double>(i + 1) * kKerbBlockM);
      if (!(s < e)) continue;
      Aabb2 block = band;
      block.min[axis] = s;
      block.max[axis] = e;
      canvas.fillConvex(rect(camera, block), i % 2 == 0 ? palette.kerb_a : palette.kerb_b);
    }
  }
}

}  // namespace cardemo
