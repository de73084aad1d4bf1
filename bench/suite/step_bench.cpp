// Whole step: one player car driving a scripted 30 s path through World::step among N parked
// cars (the lot layout), against a b2World of the same scene: static bodies for the parked cars,
// a dynamic box driven by velocity (set each step from the same drive), stepped at the same rate.

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "bench_registry.hpp"
#include "sim/world.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#endif

namespace cardemo::bench {
namespace {

constexpr double kHz = 120.0;

std::size_t driveFrames(const BenchConfig& config) {
  return config.smoke ? 240 : 3600;
}

#if defined(CARDEMO_HAVE_COMPARE)
// Velocity of our car over each step of the drive (pose change / dt, as compare-world does), so
// the b2World body follows the same path without running our integrator in its timed loop.
struct Motion {
  float vx, vy, omega;
};

std::vector<Motion> recordedMotion(const Scene& scene, const std::vector<InputFrame>& drive) {
  WorldSettings settings;
  settings.hz = kHz;
  World world(scene, settings);
  std::vector<Motion> out;
  out.reserve(drive.size());
  Eigen::Vector2d position = world.car().position;
  double heading = world.car().heading;
  for (const InputFrame& in : drive) {
    world.step(in);
    const Eigen::Vector2d v = (world.car().position - position) * kHz;
    double turn = world.car().heading - heading;
    turn -= 2.0 * std::numbers::pi * std::round(turn / (2.0 * std::numbers::pi));
    out.push_back(
        {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(turn * kHz)});
    position = world.car().position;
    heading = world.car().heading;
  }
  return out;
}

float angleOf(const Obb2& box) {
  return static_cast<float>(std::atan2(box.axis.y(), box.axis.x()));
}

// The scene as a Box2D user builds it (float positions, SetAsBox, angle from the heading).
b2Body* buildB2World(b2World& b2, const Scene& scene) {
  for (const ParkedCar& p : scene.parked) {
    b2BodyDef def;
    def.type = b2_staticBody;
    def.position.Set(static_cast<float>(p.box.center.x()), static_cast<float>(p.box.center.y()));
    def.angle = angleOf(p.box);
    b2PolygonShape polygon;
    polygon.SetAsBox(static_cast<float>(p.box.half.x()), static_cast<float>(p.box.half.y()));
    b2.CreateBody(&def)->CreateFixture(&polygon, 0.0f);
  }
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(static_cast<float>(scene.player.position.x()),
                   static_cast<float>(scene.player.position.y()));
  def.angle = static_cast<float>(scene.player.heading_deg * std::numbers::pi / 180.0);
  b2Body* car = b2.CreateBody(&def);
  b2PolygonShape polygon;
  polygon.SetAsBox(static_cast<float>(0.5 * scene.player.length),
                   static_cast<float>(0.5 * scene.player.width));
  car->CreateFixture(&polygon, 1.0f);
  return car;
}
#endif

void registerSize(std::size_t n, const BenchConfig& config) {
  const std::string prefix = "step/lot/" + sizeLabel(n) + "/";
  const std::size_t frames = driveFrames(config);
  benchmark::RegisterBenchmark(
      (prefix + "cardemo").c_str(),
      [n, frames](benchmark::State& s) {
        const std::vector<InputFrame> drive = lotDrive(frames);
        WorldSettings settings;
        settings.hz = kHz;
        World world(lotScene(n), settings);
        std::size_t k = 0;
        for (auto _ : s) world.step(drive[k++ % drive.size()]);
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
        s.counters["hits"] = static_cast<double>(world.hits().size());
        s.counters["queries"] = static_cast<double>(world.stats().broadphase_queries);
        s.counters["narrow_tests"] = static_cast<double>(world.stats().narrowphase_tests);
      })
      ->Iterations(static_cast<benchmark::IterationCount>(frames))
      ->Unit(benchmark::kNanosecond);
#if defined(CARDEMO_HAVE_COMPARE)
  // Box2D's step walks every body each step, so the large lots run a shorter prefix of the drive.
  const std::size_t b2_frames = std::max<std::size_t>(
      60, std::min<std::size_t>(frames, 200000000 / std::max<std::size_t>(n, 1)));
  benchmark::RegisterBenchmark((prefix + "box2d").c_str(),
                               [n, b2_frames](benchmark::State& s) {
                                 const Scene scene = lotScene(n);
                                 const std::vector<Motion> motion =
                                     recordedMotion(scene, lotDrive(b2_frames));
                                 b2World b2(b2Vec2(0.0f, 0.0f));
                                 b2Body* car = buildB2World(b2, scene);
                                 const float dt = static_cast<float>(1.0 / kHz);
                                 std::size_t k = 0;
                                 for (auto _ : s) {
                                   const Motion& m = motion[k++ % motion.size()];
                                   car->SetLinearVelocity(b2Vec2(m.vx, m.vy));
                                   car->SetAngularVelocity(m.omega);
                                   b2.Step(dt, 8, 3);
                                 }
                                 s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
                                 s.counters["contacts"] = static_cast<double>(b2.GetContactCount());
                               })
      ->Iterations(static_cast<benchmark::IterationCount>(b2_frames))
      ->Unit(benchmark::kNanosecond);
#endif
}

}  // namespace

void registerStep(const BenchConfig& config) {
  const std::vector<std::size_t> sizes =
      config.smoke ? std::vector<std::size_t>{100, 1000}
                   : std::vector<std::size_t>{100, 1000, 10000, 100000, 1000000};
  for (const std::size_t n : sizes) registerSize(n, config);
}

}  // namespace cardemo::bench
