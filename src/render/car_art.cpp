#include "render/car_art.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "render/shapes.hpp"

namespace cardemo {
namespace {

constexpr double kTyreLength = 0.72;  // metres
constexpr double kTyreWidth = 0.26;   // metres
// Tyres stick out of the body's side by this much, metres, so the steering shows.
constexpr double kTyreOut = 0.12;

// Points of the car in its own frame (x forward, y left), in metres from the centre.
struct Local {
  const Camera& camera;
  const Obb2& box;
  [[nodiscard]] Eigen::Vector2f at(double lx, double ly) const {
    return camera.toScreen(box.center + box.axis * lx + box.perp() * ly);
  }
  // A quad between fractions of the half extents.
  [[nodiscard]] std::array<Eigen::Vector2f, 4> quad(double x0, double x1, double y0,
                                                    double y1) const {
    const double hx = box.half.x();
    const double hy = box.half.y();
    return {at(x0 * hx, y0 * hy), at(x1 * hx, y0 * hy), at(x1 * hx, y1 * hy), at(x0 * hx, y1 * hy)};
  }
};

std::uint32_t next(std::uint32_t& s) {
  // xorshift32 (Marsaglia 2003): a dent's outline varies with its seed, the same every frame.
  s ^= s << 13;
  s ^= s >> 17;
  s ^= s << 5;
  return s;
}

// The four tyres; front ones turned by the steering angle.
void drawTyres(Canvas& canvas, const Camera& camera, const Obb2& box, const CarLook& look,
               const Palette& palette, bool sprites) {
  const double ax = std::min(0.5 * look.wheelbase, 0.8 * box.half.x());
  const double ay = box.half.y() + kTyreOut - 0.5 * kTyreWidth;
  const double heading = std::atan2(box.axis.y(), box.axis.x());
  for (int i = 0; i < 4; ++i) {
    const bool front = i < 2;
    const Eigen::Vector2d c =
        box.center + box.axis * (front ? ax : -ax) + box.perp() * (i % 2 == 0 ? ay : -ay);
    const double angle = heading + (front ? look.steer : 0.0);
    if (sprites) {
      const double ppm = camera.pixels_per_metre;
      canvas.image(ImageId::kWheel, camera.toScreen(c), static_cast<float>(-angle),
                   {static_cast<float>(kTyreLength * ppm), static_cast<float>(kTyreWidth * ppm)},
                   {255, 255, 255, 255});
      continue;
    }
    const Obb2 tyre{c, {std::cos(angle), std::sin(angle)}, {0.5 * kTyreLength, 0.5 * kTyreWidth}};
    canvas.fillConvex(projectObb(camera, tyre), palette.tyre);
  }
}

void drawLamps(Canvas& canvas, const Local& l, const CarLook& look, const Palette& palette) {
  Rgba head = look.lit ? palette.headlight : shade(palette.headlight, 0.7);
  for (const double side : {1.0, -1.0}) {
    canvas.fillConvex(l.quad(0.9, 0.99, side * 0.5, side * 0.86), head);
    canvas.fillConvex(l.quad(-0.99, -0.92, side * 0.5, side * 0.86),
                      look.braking ? palette.brake_light : palette.tail_light);
    if (look.reversing)
      canvas.fillConvex(l.quad(-0.99, -0.92, side * 0.2, side * 0.46), palette.reverse_light);
  }
  if (look.braking) {
    // A glow behind the car, so braking reads at any zoom.
    Rgba glow = palette.brake_light;
    glow.a = 70;
    canvas.fillConvex(l.quad(-1.22, -0.99, -1.0, 1.0), glow);
  }
}

void drawDent(Canvas& canvas, const Local& l, const Dent& dent, const Rgba& body) {
  constexpr int kPoints = 8;
  std::uint32_t s = dent.seed | 1u;
  std::array<Eigen::Vector2f, kPoints> pts;
  const Eigen::Vector2d half = l.box.half;
  // The dent's middle sits a little inside the body, its outline clamped to the body.
  Eigen::Vector2d mid = dent.local;
  const double r = std::min(dent.radius, 0.9 * half.y());
  if (std::abs(std::abs(mid.x()) - half.x()) < 1e-9) mid.x() -= std::copysign(0.35 * r, mid.x());
  if (std::abs(std::abs(mid.y()) - half.y()) < 1e-9) mid.y() -= std::copysign(0.35 * r, mid.y());
  for (int i = 0; i < kPoints; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kPoints;
    const double k = 0.7 + 0.3 * static_cast<double>(next(s) % 1000u) / 1000.0;
    Eigen::Vector2d p = mid + Eigen::Vector2d{std::cos(a), std::sin(a)} * (r * k);
    p = p.cwiseMax(-half).cwiseMin(half);
    pts[static_cast<std::size_t>(i)] = l.at(p.x(), p.y());
  }
  Rgba dark = shade(body, 0.5);
  dark.a = 215;
  canvas.fillConvex(pts, dark);
  // A bright crease across the dent.
  Rgba crease = shade(body, 1.45);
  crease.a = 200;
  canvas.line(pts[1], pts[5], std::max(1.0f, static_cast<float>(0.05 * l.camera.pixels_per_metre)),
              crease);
}

// Scratches that grow in number as the player's health falls (fixed places, so stable).
void drawScratches(Canvas& canvas, const Local& l, double damage) {
  constexpr std::array<std::array<double, 4>, 8> kScratches{{{0.7, 0.9, 0.3, 0.6},
                                                             {-0.8, -0.5, -0.85, -0.7},
                                                             {0.3, 0.6, -0.9, -0.75},
                                                             {-0.4, -0.1, 0.88, 0.7},
                                                             {0.75, 0.95, -0.2, -0.5},
                                                             {-0.95, -0.75, 0.1, 0.45},
                                                             {0.05, 0.35, 0.9, 0.78},
                                                             {-0.6, -0.3, -0.2, -0.4}}};
  const int n = std::clamp(static_cast<int>(std::lround(damage * 8.0)), 0, 8);
  const Rgba c{235, 235, 235, 120};
  const float w = std::max(1.0f, static_cast<float>(0.04 * l.camera.pixels_per_metre));
  const double hx = l.box.half.x();
  const double hy = l.box.half.y();
  for (int i = 0; i < n; ++i) {
    const auto& s = kScratches[static_cast<std::size_t>(i)];
    canvas.line(l.at(s[0] * hx, s[2] * hy), l.at(s[1] * hx, s[3] * hy), w, c);
  }
}

}  // namespace

void drawCarArt(Canvas& canvas, const Camera& camera, const Obb2& box, const CarLook& look,
                const Palette& palette, bool sprites) {
  const bool body_sprite = sprites && canvas.hasImage(ImageId::kCarBody);
  const bool tyre_sprite = sprites && canvas.hasImage(ImageId::kWheel);
  const Local l{camera, box};
  const double ppm = camera.pixels_per_metre;
  const float angle = static_cast<float>(-std::atan2(box.axis.y(), box.axis.x()));
  const Eigen::Vector2f size{static_cast<float>(2.0 * box.half.x() * ppm),
                             static_cast<float>(2.0 * box.half.y() * ppm)};
  // A soft shadow under the car lifts it off the ground.
  const Eigen::Vector2d off = Eigen::Vector2d{0.18, -0.22};
  const Obb2 shadow{box.center + off, box.axis, box.half + Eigen::Vector2d{0.05, 0.05}};
  canvas.fillConvex(projectObb(camera, shadow), {0, 0, 0, 70});
  drawTyres(canvas, camera, box, look, palette, tyre_sprite);
  if (body_sprite) {
    canvas.image(ImageId::kCarBody, camera.toScreen(box.center), angle, size, look.body);
  } else {
    const std::array<Eigen::Vector2f, 4> corners = projectObb(camera, box);
    canvas.fillConvex(corners, look.body);
    outline(canvas, corners, 1.5f, shade(look.body, 0.6));
    canvas.fillConvex(windscreenQuad(camera, box), palette.windscreen);
    canvas.fillConvex(l.quad(-0.74, -0.58, -0.72, 0.72), palette.rear_window);
    // Roof panel: only outlined, so the paint shows in the middle of the car.
    const auto roof = l.quad(-0.55, 0.1, -0.74, 0.74);
    outline(canvas, roof, std::max(1.0f, static_cast<float>(0.05 * ppm)), palette.roof_line);
  }
  drawLamps(canvas, l, look, palette);
  for (const Dent& d : look.dents) {
    if (d.owner == look.owner) drawDent(canvas, l, d, look.body);
  }
  if (look.damage > 0.0) drawScratches(canvas, l, look.damage);
  if (look.flash > 0.0f) {
    const auto a = static_cast<std::uint8_t>(std::lround(200.0f * look.flash));
    if (body_sprite) {
      canvas.image(ImageId::kCarBody, camera.toScreen(box.center), angle, size, {255, 255, 255, a});
    } else {
      canvas.fillConvex(projectObb(camera, box), {255, 250, 235, a});
    }
    const Obb2 ring{box.center, box.axis, box.half + Eigen::Vector2d::Constant(0.25 * look.flash)};
    outline(canvas, projectObb(camera, ring), std::max(2.0f, static_cast<float>(0.12 * ppm)),
            {255, 90, 60, a});
  }
}

}  // namespace cardemo
