#include "bench_data.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <utility>

#include "geometry/angle.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"

namespace cardemo::bench {
namespace {

constexpr double kOverlapTarget = 0.45;

Obb2 randomCar(std::mt19937_64& rng, const Eigen::Vector2d& center) {
  std::uniform_real_distribution<double> length(3.5, 5.5), width(1.6, 2.2), turn(-180.0, 180.0);
  // Width, length, heading: the order GCC took when the published pair sets were drawn, now on
  // every compiler (argument order is unspecified).
  const double car_width = width(rng);
  const double car_length = length(rng);
  const double heading = turn(rng);
  return Obb2::fromDegrees(center, heading, car_length, car_width);
}

Obb3 randomBody(std::mt19937_64& rng, const Eigen::Vector3d& center) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> size(1.0, 5.0);
  Eigen::Quaterniond q{g(rng), g(rng), g(rng), g(rng)};
  while (q.norm() < 1e-3) q = Eigen::Quaterniond{g(rng), g(rng), g(rng), g(rng)};
  return Obb3::fromQuaternion(center, q, {size(rng), size(rng), size(rng)});
}

// B placed around A at a distance drawn uniformly over a disc of radius `reach`.
template <class Make>
PairSet2 makePairs2(std::size_t n, std::uint64_t seed, double reach, bool one_query,
                    const Make& make_a) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PairSet2 set;
  set.a.reserve(one_query ? 1 : n);
  set.b.reserve(n);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!one_query || i == 0) set.a.push_back(make_a(rng));
    const Obb2& a = set.a.back();
    const double t = 2.0 * std::numbers::pi * unit(rng);
    const double r = reach * std::sqrt(unit(rng));
    set.b.push_back(randomCar(rng, a.center + r * Eigen::Vector2d(std::cos(t), std::sin(t))));
    hits += overlapObb2(a, set.b.back()) ? 1 : 0;
  }
  set.overlap_share = n > 0 ? static_cast<double>(hits) / static_cast<double>(n) : 0.0;
  return set;
}

template <class Make>
PairSet3 makePairs3(std::size_t n, std::uint64_t seed, double reach, bool one_query,
                    const Make& make_a) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> g;
  PairSet3 set;
  set.a.reserve(one_query ? 1 : n);
  set.b.reserve(n);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!one_query || i == 0) set.a.push_back(make_a(rng));
    const Obb3& a = set.a.back();
    Eigen::Vector3d dir{g(rng), g(rng), g(rng)};
    dir /= std::max(dir.norm(), 1e-9);
    set.b.push_back(randomBody(rng, a.center + reach * std::cbrt(unit(rng)) * dir));
    hits += overlapObb3(a, set.b.back()) ? 1 : 0;
  }
  set.overlap_share = n > 0 ? static_cast<double>(hits) / static_cast<double>(n) : 0.0;
  return set;
}

// Reach that gives the target share of overlapping pairs, by bisection on a sample.
template <class Share>
double calibrateReach(const Share& share_at, double lo, double hi) {
  for (int k = 0; k < 30; ++k) {
    const double mid = 0.5 * (lo + hi);
    (share_at(mid) > kOverlapTarget ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Obb2 spreadQuery2(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-1000.0, 1000.0);
  return randomCar(rng, {pos(rng), pos(rng)});
}

Obb3 spreadQuery3(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-1000.0, 1000.0);
  return randomBody(rng, {pos(rng), pos(rng), pos(rng)});
}

double reach2() {
  static const double reach = calibrateReach(
      [](double r) { return makePairs2(20000, 7, r, false, spreadQuery2).overlap_share; }, 0.5,
      20.0);
  return reach;
}

double reach3() {
  static const double reach = calibrateReach(
      [](double r) { return makePairs3(20000, 7, r, false, spreadQuery3).overlap_share; }, 0.5,
      20.0);
  return reach;
}

template <class T, class Make>
const T& cached(std::map<std::size_t, std::unique_ptr<T>>& cache, std::size_t n, const Make& make) {
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<T>(make());
  return *slot;
}

constexpr double kPitch = 2.6;
constexpr double kAisle = 7.0;
constexpr double kBlockHeight = 2 * (4.5 + 0.1) + kAisle;

// Bays per row: a roughly square lot (the bundled large lot uses 104 for 10,100 cars).
std::size_t baysPerRow(std::size_t n) {
  const double side = std::sqrt(21.0 * static_cast<double>(n));
  return std::max<std::size_t>(8, static_cast<std::size_t>(std::lround(side / kPitch)));
}

struct LotCarWithId {
  LotCar car;
  std::size_t block = 0;
  bool north = true;
  std::size_t bay = 0;
};

std::vector<LotCarWithId> lotWithIds(std::size_t n) {
  Lcg rng(20261122);
  const std::size_t per_row = baysPerRow(n);
  std::vector<LotCarWithId> cars;
  cars.reserve(n);
  for (std::size_t block = 0; cars.size() < n; ++block) {
    const double aisle_y = static_cast<double>(block) * kBlockHeight;
    for (const int side : {1, -1}) {
      const double row_y = aisle_y + side * (kAisle / 2 + 4.5 / 2 + 0.05);
      for (std::size_t k = 0; k < per_row && cars.size() < n; ++k) {
        const bool empty = rng.uniform() < 0.03;
        const double jitter_heading = (rng.uniform() - 0.5) * 6.0;
        const double jitter_x = (rng.uniform() - 0.5) * 0.3;
        const double length = 4.2 + 0.6 * rng.uniform();
        const double width = 1.7 + 0.2 * rng.uniform();
        if (empty) continue;
        const double heading = (side > 0 ? 90.0 : 270.0) + jitter_heading;
        const Eigen::Vector2d c{static_cast<double>(k) * kPitch + jitter_x, row_y};
        cars.push_back(
            {{Obb2::fromDegrees(c, heading, length, width), heading}, block, side > 0, k});
      }
    }
  }
  return cars;
}

std::size_t blocksOf(const std::vector<LotCarWithId>& cars) {
  return cars.empty() ? 1 : cars.back().block + 1;
}

// Slides a tenth of the boxes of a one-against-many set (each box with probability 0.1, seeded,
// so that no period a branch predictor could learn marks them) along the SAT normal to a signed
// gap within 1e-5 m of touching, as resting and grazing contacts are in the game (the float
// pre-filters send these on), and sets the set's overlap share. `query(a, b)` returns the pair's
// SAT result and its boolean verdict.
template <class Set, class Query>
void placeTenthNearTouching(Set& set, std::uint64_t seed, const Query& query) {
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution chosen(0.1);
  std::uniform_real_distribution<double> gap(-1e-5, 1e-5);
  std::size_t hits = 0;
  const std::size_t n = set.b.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (chosen(rng)) {
      const auto s = query(set.a[0], set.b[i]).first;
      set.b[i].center += (gap(rng) - s.separation) * s.normal;
    }
    hits += query(set.a[0], set.b[i]).second ? 1 : 0;
  }
  set.overlap_share = n > 0 ? static_cast<double>(hits) / static_cast<double>(n) : 0.0;
}

}  // namespace

const PairSet2& pairSet2(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<PairSet2>> cache;
  return cached(cache, n, [n] { return makePairs2(n, 1000 + n, reach2(), false, spreadQuery2); });
}

const PairSet2& batchSet2(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<PairSet2>> cache;
  return cached(cache, n, [n] {
    PairSet2 set = makePairs2(n, 2000 + n, reach2(), true, spreadQuery2);
    placeTenthNearTouching(set, 5000 + n, [](const Obb2& a, const Obb2& b) {
      return std::pair{collideObb2(a, b), overlapObb2(a, b)};
    });
    return set;
  });
}

const PairSet3& pairSet3(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<PairSet3>> cache;
  return cached(cache, n, [n] { return makePairs3(n, 3000 + n, reach3(), false, spreadQuery3); });
}

const PairSet3& batchSet3(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<PairSet3>> cache;
  return cached(cache, n, [n] {
    PairSet3 set = makePairs3(n, 4000 + n, reach3(), true, spreadQuery3);
    placeTenthNearTouching(set, 6000 + n, [](const Obb3& a, const Obb3& b) {
      return std::pair{collideObb3(a, b), overlapObb3(a, b)};
    });
    return set;
  });
}

std::vector<LotCar> lotLayout(std::size_t n) {
  std::vector<LotCar> cars;
  cars.reserve(n);
  for (const LotCarWithId& c : lotWithIds(n)) cars.push_back(c.car);
  return cars;
}

std::vector<LotCar> randomLayout(std::size_t n) {
  std::mt19937_64 rng(n * 31 + 5);
  const double side = std::sqrt(21.0 * static_cast<double>(n));
  std::uniform_real_distribution<double> pos(0.0, side), turn(-180.0, 180.0);
  std::uniform_real_distribution<double> length(4.2, 4.8), width(1.7, 1.9);
  std::vector<LotCar> cars;
  cars.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double heading = turn(rng);
    // As randomCar: GCC's former order, the published layouts.
    const double car_width = width(rng);
    const double car_length = length(rng);
    const Eigen::Vector2d center{pos(rng), pos(rng)};
    cars.push_back({Obb2::fromDegrees(center, heading, car_length, car_width), heading});
  }
  return cars;
}

std::vector<Aabb2> boundsOf(const std::vector<LotCar>& cars) {
  std::vector<Aabb2> out;
  out.reserve(cars.size());
  for (const LotCar& c : cars) out.push_back(c.box.aabb());
  return out;
}

std::vector<Aabb2> queryPath(const std::vector<Aabb2>& boxes, std::size_t steps) {
  Aabb2 world = boxes.empty() ? Aabb2{} : boxes[0];
  for (const Aabb2& b : boxes) world = world.merged(b);
  const Eigen::Vector2d size = world.size() + Eigen::Vector2d(10.0, 10.0);
  std::vector<Aabb2> path;
  path.reserve(steps);
  for (std::size_t i = 0; i < steps; ++i) {
    const double s = 0.25 * static_cast<double>(i);
    // Mostly along x (aisles), drifting across the rows; the heading turns slowly.
    const Eigen::Vector2d c{world.min.x() - 5.0 + std::fmod(0.93 * s, size.x()),
                            world.min.y() - 5.0 + std::fmod(0.37 * s + 3.0, size.y())};
    path.push_back(Obb2{c, unitFromRadians(0.004 * static_cast<double>(i)), {2.25, 0.9}}.aabb());
  }
  return path;
}

std::vector<Aabb2> scatteredQueries(const std::vector<Aabb2>& boxes, std::size_t count) {
  Aabb2 world = boxes.empty() ? Aabb2{} : boxes[0];
  for (const Aabb2& b : boxes) world = world.merged(b);
  std::mt19937_64 rng(count * 131 + boxes.size());
  std::uniform_real_distribution<double> x(world.min.x(), world.max.x());
  std::uniform_real_distribution<double> y(world.min.y(), world.max.y());
  std::uniform_real_distribution<double> turn(-std::numbers::pi, std::numbers::pi);
  std::vector<Aabb2> queries;
  queries.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d c{x(rng), y(rng)};
    queries.push_back(Obb2{c, unitFromRadians(turn(rng)), {2.25, 0.9}}.aabb());
  }
  return queries;
}

Scene lotScene(std::size_t n) {
  const std::vector<LotCarWithId> cars = lotWithIds(n);
  Scene scene;
  scene.name = "bench-lot";
  scene.player.position = {-10.0, static_cast<double>(blocksOf(cars) / 2) * kBlockHeight};
  scene.player.heading_deg = 0.0;
  scene.player.health = 1000000;  // the scene format's maximum
  scene.parked.reserve(cars.size());
  char id[48];
  for (const LotCarWithId& c : cars) {
    std::snprintf(id, sizeof id, "%02zu%c-%03zu", c.block, c.north ? 'N' : 'S', c.bay + 1);
    scene.parked.push_back({id, c.car.box, c.car.heading_deg});
  }
  return scene;
}

std::string lotSceneJson(std::size_t n) {
  const Scene scene = lotScene(n);
  std::string text;
  text.reserve(100 * n + 1000);
  char line[256];
  std::snprintf(line, sizeof line,
                "{\n  \"format\": \"cardemo-scene/1\",\n  \"name\": \"bench-lot\",\n"
                "  \"player\": {\"x\": %.3f, \"y\": %.3f, \"heading_deg\": 0, \"length\": 4.5, "
                "\"width\": 1.8, \"health\": %d},\n  \"parked\": [\n",
                scene.player.position.x(), scene.player.position.y(), scene.player.health);
  text += line;
  for (std::size_t i = 0; i < scene.parked.size(); ++i) {
    const ParkedCar& p = scene.parked[i];
    std::snprintf(line, sizeof line,
                  "    {\"id\": \"%s\", \"x\": %.3f, \"y\": %.3f, \"heading_deg\": %.2f, "
                  "\"length\": %.3f, \"width\": %.3f}%s\n",
                  p.id.c_str(), p.box.center.x(), p.box.center.y(), p.heading_deg,
                  2.0 * p.box.half.x(), 2.0 * p.box.half.y(),
                  i + 1 < scene.parked.size() ? "," : "");
    text += line;
  }
  text += "  ]\n}\n";
  return text;
}

}  // namespace cardemo::bench
