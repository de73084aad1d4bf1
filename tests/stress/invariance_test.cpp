// Invariance: a scene translated by 1e3..1e7 m, rotated by any angle or mirrored (with left and
// right swapped) gives the same hits, health and relative pose, frame by frame, for the bundled
// replays' inputs and for seeded random drives on the bundled scenes.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "drives.hpp"
#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "lockstep.hpp"
#include "stress_scale.hpp"

namespace cardemo::stress {
namespace {

// One drive: a scene, its settings and its inputs.
struct Drive {
  std::string name;
  Scene scene;
  WorldSettings settings;
  std::vector<InputFrame> inputs;
};

Drive replayDrive(const std::string& name) {
  const std::string path = assetPath("replays/" + name + ".replay");
  Parsed<Replay> replay = loadReplay(path);
  EXPECT_TRUE(replay.ok()) << replay.error().toString();
  Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  EXPECT_TRUE(scene.ok()) << scene.error().toString();
  return {name, std::move(scene).value(), settingsForReplay(replay.value()),
          framesOf(replay.value())};
}

std::vector<Drive> replayDrives() {
  std::vector<Drive> out;
  for (const std::string& name : bundledReplays()) out.push_back(replayDrive(name));
  return out;
}

// The parking lot with every parked car turned by a seeded random angle within +-10 degrees about
// its centre: boxes that are not axis-aligned, so that contacts have skewed normals.
Scene jitteredLot(std::uint64_t seed) {
  Parsed<Scene> scene = loadScene(assetPath("scenes/parking-lot.json"));
  EXPECT_TRUE(scene.ok()) << scene.error().toString();
  Scene s = std::move(scene).value();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(-10.0, 10.0);
  for (ParkedCar& p : s.parked) {
    p.heading_deg += turn(rng);
    p.box =
        Obb2::fromDegrees(p.box.center, p.heading_deg, 2.0 * p.box.half.x(), 2.0 * p.box.half.y());
  }
  s.name = "jittered lot";
  return s;
}

// Seeded random drives on every bundled scene and on a jittered lot, `per_scene` each, of
// `frames` frames at 120 Hz.
std::vector<Drive> randomDrives(int per_scene, std::int64_t frames, std::uint64_t seed) {
  std::vector<std::pair<std::string, Scene>> scenes;
  for (const char* file : {"parking-lot", "street", "garage", "runway", "large-lot"}) {
    Parsed<Scene> scene = loadScene(assetPath(std::string("scenes/") + file + ".json"));
    EXPECT_TRUE(scene.ok()) << scene.error().toString();
    scenes.emplace_back(file, std::move(scene).value());
  }
  scenes.emplace_back("jittered lot", jitteredLot(seed));
  std::vector<Drive> out;
  for (const auto& [name, scene] : scenes) {
    for (int k = 0; k < per_scene; ++k, ++seed) {
      out.push_back(
          {name + " drive " + std::to_string(seed), scene, {}, randomDrive(seed, frames)});
    }
  }
  return out;
}

double ulpOf(double x) {
  const double a = std::abs(x);
  return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

// Scenes span at most ~1 km around their origin (the large lot): the coordinates' magnitude is
// |T| plus that.
constexpr double kSceneExtent = 1024.0;

// Translation by T: every position carries ~ulp(|T|) of rounding per operation and a step does a
// handful of them (move, push-out, walls), so positions may drift by a few ulps per frame. Nothing
// else may change: headings, steering, speeds and impact speeds are computed from exact box axes
// and never see the absolute position, so they must agree bit for bit.
Tolerance translationTolerance(const RigidTransform& t) {
  const double u = ulpOf(std::abs(t.translate.x()) + std::abs(t.translate.y()) + kSceneExtent);
  return {4.0 * u, 4.0 * u, 0.0, 0.0, 0.0};
}

// Shortest obstacle edge of a scene (metres; infinity without obstacles).
double shortestEdge(const Scene& scene) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : scene.obstacles) {
    for (int i = 0; i < o.polygon.count; ++i) {
      shortest = std::min(
          shortest, (o.polygon.vertex((i + 1) % o.polygon.count) - o.polygon.vertex(i)).norm());
    }
  }
  return shortest;
}

// Rotation (and mirror): the scene's own coordinates are rotated with ~2 ulps of error each and
// headings are rounded differently (h + theta), ~1e-16 rad; the heading then picks up ~ulp(pi)
// per integration step, and positions inherit heading error times the distance travelled.
// Obstacles are stored as world vertices, so an edge that is not axis-aligned turns by up to
// ~2 ulp(|T|) / length when its vertices are rounded at |T|: its normal, and every speed that
// a contact with it changes, carry that relative error (measured: 1e-9 m/s on the 5 cm kerb of
// the garage at 3e6 m).
Tolerance rotationTolerance(const RigidTransform& t, const Scene& scene) {
  Tolerance tol = translationTolerance(t);
  const double u = tol.position / 4.0;
  constexpr double kMaxSpeed = 60.0;  // faster than any bundled drive reaches, m/s
  tol.position += 1e-11;
  tol.position_per_frame += 1e-12;
  tol.angle = 1e-14;
  tol.angle_per_frame = 1e-15;
  tol.speed = 1e-12 + kMaxSpeed * 4.0 * u / std::min(1.0, shortestEdge(scene));
  // CarParams: max_steer 0.6 rad, wheelbase 2.7 m, lock_speed 20 m/s. The lock m / (1 + (v/L)^2)
  // changes by at most m/L * 2/sqrt(3) * 9/16 = 0.0195 rad per m/s (at v = L/sqrt(3)); the yaw
  // rate v tan(steer) / wheelbase by tan(0.6)/2.7 = 0.25 per m/s directly, plus up to
  // 60 m/s * 0.0195 / cos^2(0.6) / 2.7 = 0.64 through the lock.
  tol.lock_gain = 0.02;
  tol.yaw_gain = 1.0;
  return tol;
}

// Worst figures per class, printed for docs/robustness.md.
struct ClassFigures {
  int runs = 0;
  std::int64_t frames = 0;
  std::size_t hits = 0;
  Deviation worst;
  void add(const LockstepResult& r) {
    ++runs;
    frames += r.frames;
    hits += r.hits;
    worst.position = std::max(worst.position, r.worst.position);
    worst.angle = std::max(worst.angle, r.worst.angle);
    worst.speed = std::max(worst.speed, r.worst.speed);
  }
  void print(const char* name) const {
    std::printf(
        "[ %s ] %d runs, %lld frames, %zu hits; worst |dpos| %.3g m, |dangle| %.3g rad, "
        "|dspeed| %.3g m/s\n",
        name, runs, static_cast<long long>(frames), hits, worst.position, worst.angle, worst.speed);
  }
};

void expectInvariant(const std::vector<Drive>& drives, const std::vector<RigidTransform>& ts,
                     bool (*tolerance_is_translation)(const RigidTransform&), const char* name) {
  ClassFigures figures;
  for (const Drive& d : drives) {
    for (const RigidTransform& t : ts) {
      // Non-axis rotations drop the walls (they are axis-aligned); the original drops them too.
      const Scene base = t.keepsAxes() ? d.scene : withoutBounds(d.scene);
      const Tolerance tol =
          tolerance_is_translation(t) ? translationTolerance(t) : rotationTolerance(t, base);
      const LockstepResult r = runLockstep(base, t, d.settings, d.inputs, tol);
      figures.add(r);
      EXPECT_EQ(r.divergence, "") << d.name << " under " << t.describe();
    }
  }
  figures.print(name);
}

bool isTranslation(const RigidTransform& t) {
  return t.rotate_deg == 0.0 && !t.mirror;
}

std::vector<RigidTransform> translations(std::uint64_t seed, int random_count) {
  std::vector<RigidTransform> out;
  for (const double magnitude : {1e3, 1e4, 1e5, 1e6, 1e7}) {
    out.push_back({{magnitude, 0.0}});
    out.push_back({{-magnitude, magnitude}});
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> log10(3.0, 7.0),
      angle(-std::numbers::pi, std::numbers::pi);
  for (int k = 0; k < random_count; ++k) {
    const double r = std::pow(10.0, log10(rng)), a = angle(rng);
    out.push_back({{r * std::cos(a), r * std::sin(a)}});
  }
  return out;
}

std::vector<RigidTransform> rotations(std::uint64_t seed, int random_count) {
  std::vector<RigidTransform> out{{{0, 0}, 90.0},  {{0, 0}, 180.0},     {{0, 0}, 270.0},
                                  {{0, 0}, -90.0}, {{0, 0}, 30.0},      {{0, 0}, 45.0},
                                  {{0, 0}, 1e-9},  {{0, 0}, 179.999999}};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> degrees(-360.0, 360.0);
  for (int k = 0; k < random_count; ++k) out.push_back({{0, 0}, degrees(rng)});
  return out;
}

std::vector<RigidTransform> mirrors(std::uint64_t seed, int random_count) {
  std::vector<RigidTransform> out{{{0, 0}, 0.0, true},
                                  {{0, 0}, 180.0, true},  // x -> -x
                                  {{1e7, -1e7}, 90.0, true},
                                  {{-3e6, 2e5}, 33.0, true}};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> degrees(-360.0, 360.0), log10(3.0, 7.0);
  for (int k = 0; k < random_count; ++k) {
    const double r = std::pow(10.0, log10(rng));
    out.push_back({{r, -r}, degrees(rng), true});
  }
  return out;
}

TEST(InvarianceReplays, Translation) {
  expectInvariant(replayDrives(), translations(0x7a01, static_cast<int>(scaled(4))), isTranslation,
                  "translation, bundled replays");
}

TEST(InvarianceReplays, Rotation) {
  expectInvariant(replayDrives(), rotations(0x7a02, static_cast<int>(scaled(4))), isTranslation,
                  "rotation, bundled replays");
}

TEST(InvarianceReplays, Mirror) {
  expectInvariant(replayDrives(), mirrors(0x7a03, static_cast<int>(scaled(2))), isTranslation,
                  "mirror, bundled replays");
}

TEST(InvarianceRandomDrives, Translation) {
  expectInvariant(randomDrives(static_cast<int>(scaled(2)), 3000, 0x7b00), translations(0x7b01, 2),
                  isTranslation, "translation, random drives");
}

TEST(InvarianceRandomDrives, Rotation) {
  expectInvariant(randomDrives(static_cast<int>(scaled(2)), 3000, 0x7c00), rotations(0x7c01, 2),
                  isTranslation, "rotation, random drives");
}

TEST(InvarianceRandomDrives, Mirror) {
  expectInvariant(randomDrives(static_cast<int>(scaled(2)), 3000, 0x7d00), mirrors(0x7d01, 2),
                  isTranslation, "mirror, random drives");
}

}  // namespace
}  // namespace cardemo::stress
