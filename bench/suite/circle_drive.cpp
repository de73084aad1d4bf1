#include "circle_drive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "bench_data.hpp"
#include "io/scene_json.hpp"

namespace cardemo::bench {
namespace {

// The constants and arithmetic of scripts/replay_speed.py, operation for operation, so every
// double comes out the same; `%.3f` rounds as Python's round(x, 3) does (exact value, ties even).
constexpr double kPitch = 2.6;
constexpr double kCarLength = 4.5;
constexpr double kAisle = 7.0;
constexpr double kBlockHeight = 2 * (kCarLength + 0.1) + kAisle;
constexpr double kClearing = 20.0;

// What `"%.3f"` writes, read back: the double the scene file holds.
double rounded3(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return std::strtod(buf, nullptr);
}

struct Placed {
  std::size_t block, bay;
  bool north;
  double x, y, heading;
};

}  // namespace

std::string circleSceneJson(std::size_t n) {
  Lcg rng(20261125u);
  const double area = static_cast<double>(n) / 2.0 * kPitch * kBlockHeight +
                      std::numbers::pi * (kClearing * kClearing);
  const double side = std::sqrt(area);
  const auto per_row = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(side / kPitch)));
  const double cx = static_cast<double>(per_row) * kPitch / 2.0;
  const double cy = side / 2.0;
  std::vector<Placed> parked;
  parked.reserve(n);
  for (std::size_t block = 0; parked.size() < n; ++block) {
    const double aisle_y = static_cast<double>(block) * kBlockHeight;
    for (const bool north : {true, false}) {
      const double sign = north ? 1.0 : -1.0;
      const double heading = north ? 90.0 : 270.0;
      const double row_y = aisle_y + sign * (kAisle / 2 + kCarLength / 2 + 0.05);
      for (std::size_t k = 0; k < per_row; ++k) {
        const double jitter_heading = (rng.uniform() - 0.5) * 6.0;
        const double jitter_x = (rng.uniform() - 0.5) * 0.3;
        const double x = static_cast<double>(k) * kPitch + jitter_x;
        if (parked.size() == n || std::hypot(x - cx, row_y - cy) < kClearing) continue;
        parked.push_back({block, k, north, x, row_y, heading + jitter_heading});
      }
    }
  }
  std::string text;
  text.reserve(120 * n + 400);
  char buf[256];
  // The walls' y come from the rounded rows, as the script takes them from the written values.
  double min_y = std::numeric_limits<double>::infinity();
  double max_y = -min_y;
  for (const Placed& p : parked) {
    min_y = std::min(min_y, rounded3(p.y));
    max_y = std::max(max_y, rounded3(p.y));
  }
  std::snprintf(buf, sizeof buf,
                "{\"format\":\"cardemo-scene/1\",\"name\":\"replay-speed-%zu\","
                "\"bounds\":{\"min\":[-20.0,%.3f],\"max\":[%.3f,%.3f]},"
                "\"player\":{\"x\":%.3f,\"y\":%.3f,\"heading_deg\":0,\"length\":4.5,"
                "\"width\":1.8,\"health\":100},\"parked\":[",
                n, min_y - 20.0, static_cast<double>(per_row) * kPitch + 20.0, max_y + 20.0, cx,
                cy - 4.0);
  text += buf;
  for (std::size_t i = 0; i < parked.size(); ++i) {
    const Placed& p = parked[i];
    std::snprintf(buf, sizeof buf,
                  "%s{\"id\":\"%03zu%c-%04zu\",\"x\":%.3f,\"y\":%.3f,\"heading_deg\":%.2f,"
                  "\"length\":4.5,\"width\":1.8}",
                  i == 0 ? "" : ",", p.block, p.north ? 'N' : 'S', p.bay + 1, p.x, p.y, p.heading);
    text += buf;
  }
  text += "]}\n";
  return text;
}

Scene circleScene(std::size_t n) {
  Parsed<Scene> scene = parseScene(circleSceneJson(n), "circle-scene");
  if (!scene.ok()) throw std::runtime_error(scene.error().toString());
  return std::move(scene).value();
}

InputFrame circleInput(std::size_t frame) {
  InputFrame in;
  in.up = frame % 12 < 4;
  in.left = true;
  return in;
}

}  // namespace cardemo::bench
