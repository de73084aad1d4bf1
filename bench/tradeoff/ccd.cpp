// Collision-detection error study: discrete, sub-stepped and continuous detection
// at speeds from 10 to 1000 m/s and several rates. For each setting, seeded random approaches of
// the player to a 5 cm kerb or a parked car lying across its path (random heading, face angle and
// phase of the target against the per-step grid of positions); per mode it counts the missed hits
// (tunnelling), the error of the first-contact time against the exact time of impact (the GMP
// oracle on the free trajectory, found without the product's sweep), and the cost in CPU ns per
// step (this thread's CPU clock, the fastest of three identical runs).
//
// Usage: cardemo_tradeoff_ccd [--quick] [--csv FILE]   (CSV on stdout without --csv; --out = --csv)
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "collision/narrow_phase.hpp"
#include "compare/exact/exact_sweep.hpp"
#include "geometry/angle.hpp"
#include "lab/sim/collision_schemes.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

struct Approach {
  Scene scene;
  StaticShape target;
  Eigen::Vector2d centre;   // the target's centre
  Eigen::Vector2d normal;   // unit, facing the player's start
  int frames = 0;           // steps simulated
  bool exact_hit = false;   // the free trajectory touches the target (exact oracle)
  double exact_time = 0.0;  // its first contact time, seconds
};

StaticShape targetShape(bool kerb, const Eigen::Vector2d& centre, double face_deg) {
  if (kerb) return ConvexPolygon::fromObb(Obb2::fromDegrees(centre, face_deg, 0.05, 12.0));
  return Obb2::fromDegrees(centre, face_deg + 90.0, 4.5, 1.8);
}

// Corners of the target, counter-clockwise.
std::vector<Eigen::Vector2d> cornersOf(const StaticShape& shape) {
  if (const Obb2* b = std::get_if<Obb2>(&shape)) {
    const auto c = b->corners();
    return {c.begin(), c.end()};
  }
  const ConvexPolygon& polygon = std::get<ConvexPolygon>(shape);
  return {polygon.vertices.begin(), polygon.vertices.begin() + polygon.count};
}

// True when an axis (the box's two, the motion's normal, the target's edge normals) separates
// the box swept by `d` from the target by more than 1 mm, far above double rounding here: a
// textbook test that shares no code with the product's sweep, used only to skip the oracle.
bool clearlyApart(const Obb2& box, const Eigen::Vector2d& d,
                  const std::vector<Eigen::Vector2d>& target) {
  std::vector<Eigen::Vector2d> swept;
  for (const Eigen::Vector2d& c : box.corners()) {
    swept.push_back(c);
    swept.push_back(c + d);
  }
  std::vector<Eigen::Vector2d> axes{box.axis, box.perp()};
  if (d.squaredNorm() > 0.0) axes.emplace_back(-d.y(), d.x());
  for (std::size_t i = 0; i < target.size(); ++i) {
    const Eigen::Vector2d e = target[(i + 1) % target.size()] - target[i];
    axes.emplace_back(-e.y(), e.x());
  }
  for (Eigen::Vector2d axis : axes) {
    axis.normalize();
    double lo_a = INFINITY, hi_a = -INFINITY, lo_b = INFINITY, hi_b = -INFINITY;
    for (const Eigen::Vector2d& p : swept) {
      lo_a = std::min(lo_a, p.dot(axis));
      hi_a = std::max(hi_a, p.dot(axis));
    }
    for (const Eigen::Vector2d& p : target) {
      lo_b = std::min(lo_b, p.dot(axis));
      hi_b = std::max(hi_b, p.dot(axis));
    }
    if (hi_a + 1e-3 < lo_b || hi_b + 1e-3 < lo_a) return true;
  }
  return false;
}

// The exact first contact of the free (collision-free) trajectory with the target, chosen
// independently of the product's sweep: every step whose swept box is not clearly apart from the
// target goes to the GMP oracle's sweep, and the first hit gives the time.
void exactContact(Approach& a, const WorldSettings& settings) {
  CarParams params = settings.car;
  params.length = a.scene.player.length;
  params.width = a.scene.player.width;
  CarState car;
  car.position = a.scene.player.position;
  car.heading = wrapRadians(a.scene.player.heading_deg * (3.14159265358979323846 / 180.0));
  car.direction = unitFromDegrees(a.scene.player.heading_deg);
  car.speed = a.scene.player.speed;
  const double dt = 1.0 / settings.hz;
  const std::vector<Eigen::Vector2d> target = cornersOf(a.target);
  auto exactSweep = [&](const Obb2& box, const Eigen::Vector2d& d) {
    if (const Obb2* b = std::get_if<Obb2>(&a.target)) return exact::sweepObb2(box, d, *b);
    return exact::sweepObbPolygon(box, d, std::get<ConvexPolygon>(a.target));
  };
  for (int k = 1; k <= a.frames; ++k) {
    const CarState next = integrateCar(car, InputFrame{}, params, dt);
    CarState turned = car;
    turned.heading = next.heading;
    turned.direction = next.direction;
    const Obb2 box = carBox(turned, params);
    const Eigen::Vector2d d = next.position - car.position;
    if (!clearlyApart(box, d, target)) {
      const exact::ExactSweep x = exactSweep(box, d);
      if (x.hit) {
        a.exact_hit = true;
        a.exact_time = (k - 1 + x.toi) * dt;
        return;
      }
    }
    car = next;
  }
}

std::vector<Approach> approaches(int count, double hz, double speed, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Approach> out;
  WorldSettings settings;
  settings.hz = hz;
  const double step = speed / hz;
  for (int i = 0; i < count; ++i) {
    Approach a;
    const double heading = 360.0 * unit(rng);
    const double face = -50.0 + 100.0 * unit(rng);
    const double distance = 12.0 + step * unit(rng);  // the phase against the step grid
    const bool kerb = i % 2 == 0;
    a.centre = unitFromDegrees(heading) * distance;
    a.target = targetShape(kerb, a.centre, heading + face);
    a.normal = -unitFromDegrees(heading + face);
    a.scene.name = "ccd";
    a.scene.player.heading_deg = heading;
    a.scene.player.speed = speed;
    if (kerb) {
      a.scene.obstacles.push_back({"target", std::get<ConvexPolygon>(a.target)});
    } else {
      a.scene.parked.push_back({"target", std::get<Obb2>(a.target), heading + face + 90.0});
    }
    a.frames = static_cast<int>(std::ceil(30.0 / step)) + 3;
    exactContact(a, settings);
    out.push_back(std::move(a));
  }
  return out;
}

// CPU time of this thread, ns (not wall time: a preempted run does not count the wait).
double threadNanos() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

struct Row {
  int cases = 0, missed = 0, timed = 0;
  double err_sum = 0.0, err_max = 0.0;
  double ns_per_step = 0.0;
};

// The detection modes compared: the lab's two (lab/sim/collision_schemes) and the game's.
enum class Mode { kDiscrete, kSubstepped, kContinuous };

// The fraction of its step at which the last step's scheme found contact (the study runs one world
// at a time, on one thread): where in the step a hit's first contact lies.
double last_step_fraction = 1.0;

template <MotionScheme kScheme>
double recorded(StepMotion& motion, const CarState& start, const CarState& next) {
  last_step_fraction = kScheme(motion, start, next);
  return last_step_fraction;
}

double continuous(StepMotion& motion, const CarState& start, const CarState& next) {
  return motion.continuous(start, next);
}

MotionScheme schemeOf(Mode mode) {
  switch (mode) {
    case Mode::kDiscrete:
      return recorded<moveDiscrete>;
    case Mode::kSubstepped:
      return recorded<moveSubstepped>;
    case Mode::kContinuous:
      break;
  }
  return recorded<continuous>;
}

// The fraction of the step at which the first hit's contact was found.
double firstHitFraction(const Approach& a, const WorldSettings& settings) {
  World world(a.scene, settings);
  double fraction = 1.0;
  for (int f = 0; f < a.frames && world.hits().empty(); ++f) {
    world.step(InputFrame{});
    fraction = last_step_fraction;
  }
  return fraction;
}

Row run(const std::vector<Approach>& cases, double hz, Mode mode) {
  Row row;
  WorldSettings settings;
  settings.hz = hz;
  settings.schemes.motion = schemeOf(mode);
  std::int64_t steps = 0;
  double ns = 0.0;
  for (const Approach& a : cases) {
    if (!a.exact_hit) continue;
    ++row.cases;
    // The fastest of three identical runs: the machine is shared, and a run that was preempted
    // says nothing about the code.
    double best = INFINITY;
    World world(a.scene, settings);
    for (int repeat = 0; repeat < 3; ++repeat) {
      world = World(a.scene, settings);
      const double t0 = threadNanos();
      for (int f = 0; f < a.frames; ++f) world.step(InputFrame{});
      best = std::min(best, threadNanos() - t0);
    }
    ns += best;
    steps += a.frames;
    const bool crossed = (world.car().position - a.centre).dot(a.normal) <= 0.0;
    if (world.hits().empty() || crossed) {
      ++row.missed;
      continue;
    }
    const HitEvent& h = world.hits().front();
    const double t = (static_cast<double>(h.frame) - 1.0 + firstHitFraction(a, settings)) / hz;
    const double err = std::abs(t - a.exact_time);
    ++row.timed;
    row.err_sum += err;
    row.err_max = std::max(row.err_max, err);
  }
  row.ns_per_step = steps > 0 ? ns / static_cast<double>(steps) : 0.0;
  return row;
}

const char* modeName(Mode m) {
  switch (m) {
    case Mode::kDiscrete:
      return "discrete";
    case Mode::kSubstepped:
      return "substepped";
    case Mode::kContinuous:
      return "continuous";
  }
  return "?";
}

int runStudy(int argc, char** argv) {
  bool quick = false;
  std::string out_path;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if ((std::strcmp(argv[i], "--csv") == 0 || std::strcmp(argv[i], "--out") == 0) &&
               i + 1 < argc) {
      out_path = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  const std::vector<double> rates =
      quick ? std::vector<double>{30, 120} : std::vector<double>{30, 60, 120, 240, 480};
  const std::vector<double> speeds = quick ? std::vector<double>{10, 100, 1000}
                                           : std::vector<double>{10, 20, 50, 100, 200, 500, 1000};
  const int count = quick ? 16 : 1000;
  std::ostringstream csv;
  csv << "mode,hz,speed_mps,cases,missed,toi_err_mean_s,toi_err_max_s,ns_per_step\n";
  std::uint64_t seed = 1;
  for (const double hz : rates) {
    for (const double speed : speeds) {
      const std::vector<Approach> cases = approaches(count, hz, speed, seed++);
      for (const Mode mode : {Mode::kDiscrete, Mode::kSubstepped, Mode::kContinuous}) {
        const Row r = run(cases, hz, mode);
        char line[256];
        if (r.timed > 0) {
          std::snprintf(line, sizeof line, "%s,%g,%g,%d,%d,%.6g,%.6g,%.1f\n", modeName(mode), hz,
                        speed, r.cases, r.missed, r.err_sum / r.timed, r.err_max, r.ns_per_step);
        } else {
          // Every case tunnelled: there is no first contact to time, so the error fields are empty.
          std::snprintf(line, sizeof line, "%s,%g,%g,%d,%d,,,%.1f\n", modeName(mode), hz, speed,
                        r.cases, r.missed, r.ns_per_step);
        }
        csv << line;
      }
    }
  }
  if (out_path.empty()) {
    std::cout << csv.str();
    return 0;
  }
  std::ofstream file(out_path);
  file << csv.str();
  if (!file) {
    std::fprintf(stderr, "%s:1: cannot write the CSV\n", out_path.c_str());
    return 2;
  }
  return 0;
}

}  // namespace
}  // namespace cardemo

int main(int argc, char** argv) {
  return cardemo::runStudy(argc, argv);
}
