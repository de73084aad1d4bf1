// Whole step: one player car driving along a row of parked cars (lot_drive.hpp) through
// World::step among N parked cars, against b2World::Step of the same scene in the two forms a
// Box2D user builds: one static body holding N fixtures (`box2d`), and one static body per car
// (`box2d_bodies`); `box2d_alone` is the same b2World::Step with the car alone (no parked car), the
// part of Box2D's time that is its solver and bookkeeping, not collision. The Box2D car is a
// dynamic box placed at our car's pose before each step (SetTransform) and given our car's velocity
// over that step, so it meets the same parked cars even after Box2D's solver has pushed it
// elsewhere. Every row times the whole drive except its first step (Box2D creates its contacts
// there), which is reported apart as the counter `first_step_us`. `step/circling/N/cardemo` is
// World::step alone on the circling replay of scripts/replay_speed.py (same scene, same keys), the
// like-for-like figure for `cardemo replay`.

#include <benchmark/benchmark.h>
#include <time.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "bench_registry.hpp"
#include "circle_drive.hpp"
#include "lot_drive.hpp"
#include "sim/world.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
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

// Our car's pose at the start of each step of the drive and its velocity over the step (pose
// change / dt, as compare-world does), so the b2World body follows the same path without running
// our integrator in its timed loop.
struct Motion {
  float x, y, angle, vx, vy, omega;
};

// The scene, its drive and the drive's motion; one size at a time (the 1M lot is large).
struct StepCase {
  std::size_t n = 0;
  Scene scene;
  LotDrive drive;
  std::vector<Motion> motion;
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
    const Motion start{static_cast<float>(position.x()),
                       static_cast<float>(position.y()),
                       static_cast<float>(heading),
                       0.0f,
                       0.0f,
                       0.0f};
    world.step(in);
    const Eigen::Vector2d v = (world.car().position - position) * kHz;
    double turn = world.car().heading - heading;
    turn -= 2.0 * std::numbers::pi * std::round(turn / (2.0 * std::numbers::pi));
    out.push_back({start.x, start.y, start.angle, static_cast<float>(v.x()),
                   static_cast<float>(v.y()), static_cast<float>(turn * kHz)});
    position = world.car().position;
    heading = world.car().heading;
  }
  return out;
}

const StepCase& stepCase(std::size_t n, std::size_t frames) {
  static std::unique_ptr<StepCase> last;
  if (!last || last->n != n || last->drive.inputs.size() != frames) {
    last.reset();
    auto c = std::make_unique<StepCase>();
    c->n = n;
    c->scene = lotScene(n);
    c->drive = lotDrive(c->scene, frames, kHz);
    c->motion = recordedMotion(c->scene, c->drive.inputs);
    last = std::move(c);
  }
  return *last;
}

// CPU time of this thread, microseconds (for the untimed first step).
double threadMicros() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
}

void reportDrive(benchmark::State& s, const StepCase& c) {
  s.counters["near_share"] = c.drive.near_share;
  s.counters["contact_share"] = c.drive.contact_share;
}

void runCardemo(benchmark::State& s, std::size_t n, std::size_t frames) {
  const StepCase& c = stepCase(n, frames);
  const std::vector<InputFrame>& drive = c.drive.inputs;
  WorldSettings settings;
  settings.hz = kHz;
  World world(c.scene, settings);
  const double t0 = threadMicros();
  world.step(drive[0]);
  const double first = threadMicros() - t0;
  const WorldStats before = world.stats();
  std::size_t k = 1;
  for (auto _ : s) {
    // The row runs a fixed count, one step per frame of the drive; stop rather than read past
    // the drive's end if a run ever asks for more.
    if (k == drive.size()) [[unlikely]] {
      s.SkipWithError("the drive has run out: the row runs a fixed count of steps");
      break;
    }
    world.step(drive[k++]);
  }
  const double steps = static_cast<double>(s.iterations());
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
  s.counters["first_step_us"] = first;
  s.counters["hits"] = static_cast<double>(world.hits().size());
  s.counters["narrow_per_step"] =
      static_cast<double>(world.stats().narrowphase_tests - before.narrowphase_tests) / steps;
  s.counters["contacts_per_step"] =
      static_cast<double>(world.stats().contacts - before.contacts) / steps;
  reportDrive(s, c);
}

// The circling replay of scripts/replay_speed.py (circle_drive.hpp) on its scene, one size at a
// time: World::step on exactly the input `cardemo replay` runs there, for a like-for-like ratio.
const Scene& circleCase(std::size_t n) {
  static std::unique_ptr<std::pair<std::size_t, Scene>> last;
  if (!last || last->first != n) {
    last.reset();
    last = std::make_unique<std::pair<std::size_t, Scene>>(n, circleScene(n));
  }
  return last->second;
}

// Steps before the timed ones (5 min of game time): throttle a third of the time brings the car
// to its circling speed (10.64 m/s) in about 30,000 steps, and the 2M-frame replay is almost all
// circling at that speed.
constexpr std::size_t kCircleWarmup = 36000;

void runCircling(benchmark::State& s, std::size_t n) {
  WorldSettings settings;
  settings.hz = kHz;
  World world(circleCase(n), settings);
  std::size_t k = 0;
  while (k < kCircleWarmup) world.step(circleInput(k++));
  const WorldStats before = world.stats();
  const double speed = world.car().speed;
  for (auto _ : s) world.step(circleInput(k++));
  const double steps = static_cast<double>(s.iterations());
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
  s.counters["speed_mps"] = speed;
  s.counters["hits"] = static_cast<double>(world.hits().size());
  s.counters["narrow_per_step"] =
      static_cast<double>(world.stats().narrowphase_tests - before.narrowphase_tests) / steps;
  s.counters["contacts_per_step"] =
      static_cast<double>(world.stats().contacts - before.contacts) / steps;
}

#if defined(CARDEMO_HAVE_COMPARE)
float angleOf(const Obb2& box) {
  return static_cast<float>(std::atan2(box.axis.y(), box.axis.x()));
}

b2Vec2 floatPoint(const Eigen::Vector2d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y())};
}

// How the b2World holds the parked cars.
enum class B2Lot {
  kOneBody,     // fixtures of one static body
  kBodyPerCar,  // a static body each
  kNone,        // none: the car alone
};

// The scene as a Box2D user builds it (float positions, SetAsBox, angle from the heading): the
// parked cars as fixtures of one static body at the origin, or each as its own static body.
b2Body* buildB2World(b2World& b2, const Scene& scene, B2Lot form) {
  const bool body_per_car = form == B2Lot::kBodyPerCar;
  b2BodyDef lot_def;
  b2Body* lot = form == B2Lot::kOneBody ? b2.CreateBody(&lot_def) : nullptr;
  const std::size_t parked = form == B2Lot::kNone ? 0 : scene.parked.size();
  for (std::size_t i = 0; i < parked; ++i) {
    const ParkedCar& p = scene.parked[i];
    b2PolygonShape polygon;
    const float hx = static_cast<float>(p.box.half.x());
    const float hy = static_cast<float>(p.box.half.y());
    if (body_per_car) {
      b2BodyDef def;
      def.type = b2_staticBody;
      def.position = floatPoint(p.box.center);
      def.angle = angleOf(p.box);
      polygon.SetAsBox(hx, hy);
      b2.CreateBody(&def)->CreateFixture(&polygon, 0.0f);
    } else {
      polygon.SetAsBox(hx, hy, floatPoint(p.box.center), angleOf(p.box));
      lot->CreateFixture(&polygon, 0.0f);
    }
  }
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = floatPoint(scene.player.position);
  def.angle = static_cast<float>(scene.player.heading_deg * std::numbers::pi / 180.0);
  b2Body* car = b2.CreateBody(&def);
  b2PolygonShape polygon;
  polygon.SetAsBox(static_cast<float>(0.5 * scene.player.length),
                   static_cast<float>(0.5 * scene.player.width));
  car->CreateFixture(&polygon, 1.0f);
  return car;
}

void runBox2d(benchmark::State& s, std::size_t n, std::size_t frames, B2Lot form) {
  const StepCase& c = stepCase(n, frames);
  b2World b2(b2Vec2(0.0f, 0.0f));
  b2Body* car = buildB2World(b2, c.scene, form);
  const float dt = static_cast<float>(1.0 / kHz);
  const auto drive = [&](const Motion& m) {
    car->SetTransform(b2Vec2(m.x, m.y), m.angle);
    car->SetLinearVelocity(b2Vec2(m.vx, m.vy));
    car->SetAngularVelocity(m.omega);
    b2.Step(dt, 8, 3);
  };
  const double t0 = threadMicros();
  drive(c.motion[0]);
  const double first = threadMicros() - t0;
  // After a step, the contact list holds the pairs the next step's b2CollidePolygons evaluates
  // (fat AABBs overlapping); touching ones are the contacts.
  std::int64_t narrow = 0, touching = 0;
  std::size_t k = 1;
  for (auto _ : s) {
    if (k == c.motion.size()) [[unlikely]] {  // as in runCardemo
      s.SkipWithError("the drive has run out: the row runs a fixed count of steps");
      break;
    }
    drive(c.motion[k++]);
    narrow += b2.GetContactCount();
    for (const b2Contact* ct = b2.GetContactList(); ct != nullptr; ct = ct->GetNext()) {
      touching += ct->IsTouching() ? 1 : 0;
    }
  }
  const double steps = static_cast<double>(s.iterations());
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
  s.counters["first_step_us"] = first;
  s.counters["narrow_per_step"] = static_cast<double>(narrow) / steps;
  s.counters["contacts_per_step"] = static_cast<double>(touching) / steps;
  reportDrive(s, c);
}
#endif

void registerSize(std::size_t n, const BenchConfig& config) {
  const std::string prefix = "step/lot/" + sizeLabel(n) + "/";
  const std::size_t frames = driveFrames(config);
  const auto iterations = static_cast<benchmark::IterationCount>(frames - 1);
  benchmark::RegisterBenchmark((prefix + "cardemo").c_str(),
                               [n, frames](benchmark::State& s) { runCardemo(s, n, frames); })
      ->Iterations(iterations)
      ->Unit(benchmark::kNanosecond);
#if defined(CARDEMO_HAVE_COMPARE)
  benchmark::RegisterBenchmark(
      (prefix + "box2d").c_str(),
      [n, frames](benchmark::State& s) { runBox2d(s, n, frames, B2Lot::kOneBody); })
      ->Iterations(iterations)
      ->Unit(benchmark::kNanosecond);
  // A body per car makes b2World::Step walk N bodies a step (about 0.1 s at 1M cars, so 6 min
  // for the drive): that form runs up to 100k cars.
  if (n <= 100000) {
    benchmark::RegisterBenchmark(
        (prefix + "box2d_bodies").c_str(),
        [n, frames](benchmark::State& s) { runBox2d(s, n, frames, B2Lot::kBodyPerCar); })
        ->Iterations(iterations)
        ->Unit(benchmark::kNanosecond);
  }
  benchmark::RegisterBenchmark(
      (prefix + "box2d_alone").c_str(),
      [n, frames](benchmark::State& s) { runBox2d(s, n, frames, B2Lot::kNone); })
      ->Iterations(iterations)
      ->Unit(benchmark::kNanosecond);
#endif
}

}  // namespace

void registerStep(const BenchConfig& config) {
  const std::vector<std::size_t> sizes =
      config.smoke ? std::vector<std::size_t>{100, 1000}
                   : std::vector<std::size_t>{100, 1000, 10000, 100000, 1000000};
  for (const std::size_t n : sizes) registerSize(n, config);
  const std::vector<std::size_t> circling =
      config.smoke ? std::vector<std::size_t>{1000} : std::vector<std::size_t>{1000, 100000};
  for (const std::size_t n : circling) {
    benchmark::RegisterBenchmark(("step/circling/" + sizeLabel(n) + "/cardemo").c_str(),
                                 [n](benchmark::State& s) { runCircling(s, n); })
        ->Iterations(static_cast<benchmark::IterationCount>(driveFrames(config)))
        ->Unit(benchmark::kNanosecond);
  }
}

}  // namespace cardemo::bench
