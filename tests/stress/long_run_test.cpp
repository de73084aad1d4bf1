// Long runs: circling and random driving for 1e5 frames (CI) or 1e7 (scripts/stress.sh, scale
// 100). Every frame the state is finite, the heading is wrapped to (-pi, pi], the speed stays
// within what the car model can reach, the direction is a unit vector equal to (cos, sin) of the
// heading to a few ulps, and the car stays inside the walls.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "drives.hpp"
#include "io/scene_json.hpp"
#include "sim/contact_response.hpp"
#include "sim/world.hpp"
#include "stress_scale.hpp"

namespace cardemo::stress {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Largest forward speed the model reaches from rest: throttle and drag balance where
// engine_accel = drag v^2 + rolling_resistance; the state is read after one step's throttle,
// which can add engine_accel * dt on top.
double forwardLimit(const CarParams& p, double dt) {
  return std::sqrt((p.engine_accel - p.rolling_resistance) / p.drag) + p.engine_accel * dt;
}

// Checks one frame; returns an empty string or what is wrong.
std::string checkState(const World& w, double max_forward, double max_reverse) {
  const CarState& c = w.car();
  std::ostringstream why;
  why.precision(17);
  why << "frame " << w.frame() << ": ";
  if (!c.position.allFinite() || !c.direction.allFinite() || !std::isfinite(c.heading) ||
      !std::isfinite(c.speed) || !std::isfinite(c.steer)) {
    why << "not finite: position " << c.position.transpose() << ", heading " << c.heading
        << ", direction " << c.direction.transpose() << ", speed " << c.speed << ", steer "
        << c.steer;
    return why.str();
  }
  if (!(c.heading > -std::numbers::pi && c.heading <= std::numbers::pi)) {
    why << "heading " << c.heading << " outside (-pi, pi]";
    return why.str();
  }
  if (!(c.speed <= max_forward && c.speed >= -max_reverse)) {
    why << "speed " << c.speed << " outside [" << -max_reverse << ", " << max_forward << "]";
    return why.str();
  }
  const double norm_error = std::abs(c.direction.norm() - 1.0);
  if (!(norm_error <= 2.0 * kEps)) {
    why << "|direction| - 1 = " << norm_error;
    return why.str();
  }
  const Eigen::Vector2d expected{std::cos(c.heading), std::sin(c.heading)};
  if (!((c.direction - expected).cwiseAbs().maxCoeff() <= 2.0 * kEps)) {
    why << "direction " << c.direction.transpose() << " is not (cos, sin) of heading " << c.heading;
    return why.str();
  }
  if (!(std::abs(c.steer) <= w.settings().car.max_steer)) {
    why << "steer " << c.steer << " beyond the lock";
    return why.str();
  }
  if (w.scene().bounds) {
    const Aabb2 box = w.carBox().aabb();
    const Aabb2& walls = *w.scene().bounds;
    // Walls push a car that went deeper back to the resting penetration (contact_response.hpp),
    // and a turn at the wall may take it slightly deeper before the next push: allow twice that,
    // plus the rounding of the shift.
    const double slack = 4.0 * kEps * (walls.max - walls.min).cwiseAbs().maxCoeff() +
                         2.0 * restingPenetration(w.car().position);
    if (!(box.min.x() >= walls.min.x() - slack && box.min.y() >= walls.min.y() - slack &&
          box.max.x() <= walls.max.x() + slack && box.max.y() <= walls.max.y() + slack)) {
      why << "car bounds " << box.min.transpose() << " .. " << box.max.transpose()
          << " leave the walls";
      return why.str();
    }
  }
  return {};
}

// Figures of one long run.
struct RunFigures {
  std::int64_t frames = 0;
  double max_speed = 0.0;
  double min_speed = 0.0;
  double worst_norm = 0.0;     // max | |direction| - 1 |
  double worst_cos_sin = 0.0;  // max |direction - (cos, sin)(heading)|
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
};

// Steps `w` for `frames` frames with inputs from `input(k)`, checking every frame.
template <class Input>
RunFigures runChecked(World& w, std::int64_t frames, Input input) {
  const double dt = 1.0 / w.settings().hz;
  const CarParams& p = w.settings().car;
  const double initial = std::abs(w.car().speed);
  const double max_forward = std::max(forwardLimit(p, dt), initial);
  const double max_reverse = std::max(p.max_reverse_speed, initial);
  RunFigures f;
  for (std::int64_t k = 0; k < frames; ++k) {
    w.step(input(k));
    const std::string why = checkState(w, max_forward, max_reverse);
    if (!why.empty()) {
      ADD_FAILURE() << why;
      break;
    }
    const CarState& c = w.car();
    ++f.frames;
    f.max_speed = std::max(f.max_speed, c.speed);
    f.min_speed = std::min(f.min_speed, c.speed);
    f.worst_norm = std::max(f.worst_norm, std::abs(c.direction.norm() - 1.0));
    f.worst_cos_sin =
        std::max(f.worst_cos_sin,
                 (c.direction - Eigen::Vector2d(std::cos(c.heading), std::sin(c.heading))).norm());
    f.low = f.low.cwiseMin(c.position);
    f.high = f.high.cwiseMax(c.position);
  }
  return f;
}

Scene openGround(const Eigen::Vector2d& at) {
  Scene s;
  s.name = "open ground";
  s.player.position = at;
  return s;
}

// Circling at full lock and full throttle: after the speed settles the car traces the same circle
// for ever; its bounding box must not drift.
void circle(const Eigen::Vector2d& at, std::uint64_t frames, const char* name) {
  World w(openGround(at));
  const InputFrame throttle_left{true, false, true, false};
  // Settle: the speed and the lock converge within a minute of game time.
  (void)runChecked(w, 120 * 60, [&](std::int64_t) { return throttle_left; });
  const RunFigures first = runChecked(w, 120 * 60, [&](std::int64_t) { return throttle_left; });
  const RunFigures rest =
      runChecked(w, static_cast<std::int64_t>(frames), [&](std::int64_t) { return throttle_left; });
  const Eigen::Vector2d centre0 = 0.5 * (first.low + first.high);
  const Eigen::Vector2d centre1 = 0.5 * (rest.low + rest.high);
  const double radius = 0.5 * (first.high - first.low).maxCoeff();
  const double drift = (centre1 - centre0).norm();
  const double growth = std::abs(0.5 * (rest.high - rest.low).maxCoeff() - radius);
  std::printf(
      "[ %s ] %lld frames: radius %.6f m, speed %.6f m/s, bounding-box centre drift %.3g m, "
      "radius change %.3g m, worst | |dir| - 1 | %.3g, worst |dir - (cos, sin)| %.3g\n",
      name, static_cast<long long>(rest.frames), radius, w.car().speed, drift, growth,
      rest.worst_norm, rest.worst_cos_sin);
  // One lap at ~49 m/s on a ~20 m circle is ~300 frames: a frame's travel (0.4 m) lands the
  // extremes up to the chord's sagitta inside the true circle, (0.4)^2 / (8 * 20) = 1 mm.
  EXPECT_LE(drift, 2e-3) << name;
  EXPECT_LE(growth, 2e-3) << name;
}

TEST(LongRun, CirclingAtTheOrigin) {
  circle({0.0, 0.0}, static_cast<std::uint64_t>(scaled(100000)), "circling at the origin");
}

TEST(LongRun, CirclingFarOut) {
  circle({1e7, -1e7}, static_cast<std::uint64_t>(scaled(100000)), "circling at (1e7, -1e7)");
}

// Random driving in the walled parking lot with damage off, so the game never ends and the car
// keeps hitting cars and walls.
void randomDriving(const std::string& scene_file, std::uint64_t seed, const char* name) {
  Parsed<Scene> scene = loadScene(assetPath("scenes/" + scene_file));
  ASSERT_TRUE(scene.ok()) << scene.error().toString();
  WorldSettings settings;
  settings.damage_min = 0;
  settings.damage_max = 0;
  World w(std::move(scene).value(), settings);
  const std::int64_t frames = scaled(100000);
  // A random drive of 2e5 frames, replayed cyclically (generating 1e7 frames would cost memory).
  const std::vector<InputFrame> drive = randomDrive(seed, 200000);
  const RunFigures f = runChecked(w, frames, [&](std::int64_t k) {
    return drive[static_cast<std::size_t>(k % static_cast<std::int64_t>(drive.size()))];
  });
  std::printf(
      "[ %s ] %lld frames, %zu hits, speed %.3f..%.3f m/s, worst | |dir| - 1 | %.3g, worst |dir - "
      "(cos, sin)| %.3g\n",
      name, static_cast<long long>(f.frames), w.hits().size(), f.min_speed, f.max_speed,
      f.worst_norm, f.worst_cos_sin);
  EXPECT_EQ(f.frames, frames);
  EXPECT_GT(w.hits().size(), 0u) << "the drive should hit something";
}

TEST(LongRun, RandomDrivingInTheParkingLot) {
  randomDriving("parking-lot.json", 0x10a1, "random driving, parking lot");
}

TEST(LongRun, RandomDrivingInTheGarage) {
  randomDriving("garage.json", 0x10a2, "random driving, garage");
}

}  // namespace
}  // namespace cardemo::stress
