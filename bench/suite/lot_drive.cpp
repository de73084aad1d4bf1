#include "lot_drive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/sat_obb2.hpp"
#include "sim/world.hpp"

namespace cardemo::bench {
namespace {

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Corners of one box against the edges of the other: the distance of separated convex polygons.
double cornersToEdges(const Obb2& a, const Obb2& b) {
  const auto ca = a.corners();
  const auto cb = b.corners();
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : ca) {
    for (std::size_t j = 0; j < 4; ++j) {
      best = std::min(best, pointSegmentDistance(p, cb[j], cb[(j + 1) % 4]));
    }
  }
  return best;
}

}  // namespace

double boxDistance(const Obb2& a, const Obb2& b) {
  if (overlapObb2(a, b)) return 0.0;
  return std::min(cornersToEdges(a, b), cornersToEdges(b, a));
}

LotDrive lotDrive(const Scene& scene, std::size_t frames, double hz) {
  const double y0 = scene.player.position.y();
  // The parked cars the drive can reach: both rows along the middle aisle.
  std::vector<Obb2> near;
  double row_end = 0.0;
  for (const ParkedCar& p : scene.parked) {
    if (std::abs(p.box.center.y() - y0) > 8.0) continue;
    row_end = std::max(row_end, p.box.center.x());
    if (p.box.center.x() < 120.0) near.push_back(p.box);
  }
  const double x_near = 4.0;
  const double x_far = std::min(row_end - 4.0, 90.0);
  // North bumpers lie 3.4-3.7 m from the aisle's centre line; the car is 1.8 m wide.
  const double hold_y = y0 + 3.4 - 0.9 - 0.3;
  const double graze_y = y0 + 3.4 - 0.9 + 0.4;
  const std::size_t graze_period = static_cast<std::size_t>(4.0 * hz);
  const std::size_t graze_length = static_cast<std::size_t>(0.75 * hz);

  WorldSettings settings;
  settings.hz = hz;
  World world(scene, settings);
  LotDrive out;
  out.inputs.reserve(frames);
  bool forward = true;
  std::size_t near_frames = 0, contact_frames = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    const CarState& car = world.car();
    if (forward && car.position.x() > x_far) forward = false;
    if (!forward && car.position.x() < x_near) forward = true;
    const double target_y = f % graze_period < graze_length ? graze_y : hold_y;
    // Heading that closes the lateral gap (moving backwards the car moves against its heading).
    const double steer_to = std::clamp(0.3 * (target_y - car.position.y()), -0.2, 0.2);
    const double want = forward ? steer_to : -steer_to;
    InputFrame in;
    if (forward) {
      in.up = car.speed < 6.0;
    } else {
      in.down = car.speed > -4.0;
    }
    // Left turns the heading up when moving forward, down when moving backwards.
    const bool raise = car.heading < want - 0.01;
    const bool lower = car.heading > want + 0.01;
    const bool backwards = car.speed < 0.0;
    in.left = backwards ? lower : raise;
    in.right = backwards ? raise : lower;
    world.step(in);
    out.inputs.push_back(in);
    const Obb2 box = world.carBox();
    double nearest = std::numeric_limits<double>::infinity();
    for (const Obb2& b : near) nearest = std::min(nearest, boxDistance(box, b));
    near_frames += nearest <= 1.0 ? 1 : 0;
    contact_frames += world.contacts().empty() ? 0 : 1;
  }
  const double n = static_cast<double>(std::max<std::size_t>(frames, 1));
  out.near_share = static_cast<double>(near_frames) / n;
  out.contact_share = static_cast<double>(contact_frames) / n;
  out.hits = world.hits().size();
  return out;
}

}  // namespace cardemo::bench
