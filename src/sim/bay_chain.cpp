#include "sim/bay_chain.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <unordered_map>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/sat_obb2.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

// Positions closer than this (m) are the same slot; headings and sizes equal within it match.
constexpr double kSame = 1e-6;

struct Row {
  std::vector<const ParkedCar*> cars;
};

bool sameKind(const ParkedCar& a, const ParkedCar& b) {
  const double turn = std::remainder(a.heading_deg - b.heading_deg, 360.0);
  return std::abs(turn) < kSame && std::abs(a.box.half.x() - b.box.half.x()) < kSame &&
         std::abs(a.box.half.y() - b.box.half.y()) < kSame;
}

// Headings in [0, 360), as the kinds are looked up.
double headingKey(double heading_deg) {
  double h = std::fmod(heading_deg, 360.0);
  if (h < 0.0) h += 360.0;
  return h >= 360.0 ? 0.0 : h;
}

// A cell of (heading, half length, half width) space, kCell wide on each axis: two cars of one
// kind (sameKind) lie in the same cell or neighbouring ones.
constexpr double kCell = 2.0 * kSame;

struct KindCell {
  double heading, half_length, half_width;  // cell indices, as doubles (sizes may be huge)
  bool operator==(const KindCell&) const = default;
};

struct KindCellHash {
  std::size_t operator()(const KindCell& c) const {
    const std::hash<double> h;
    return h(c.heading) ^ (h(c.half_length) * 31u) ^ (h(c.half_width) * 1000003u);
  }
};

KindCell kindCell(double heading_key, double half_length, double half_width) {
  return {std::floor(heading_key / kCell), std::floor(half_length / kCell),
          std::floor(half_width / kCell)};
}

// Cars grouped by kind in scene order: a car joins the earliest group whose first car is of its
// kind, as a scan of every group would, but looks only in the neighbouring cells, so that a lot
// of 10,000 cars of as many kinds groups in linear time, not quadratic.
std::vector<Row> groupByKind(const std::vector<ParkedCar>& parked) {
  std::vector<Row> kinds;
  std::unordered_map<KindCell, std::vector<std::size_t>, KindCellHash> leaders;
  for (const ParkedCar& car : parked) {
    const double h = headingKey(car.heading_deg);
    const double hx = car.box.half.x();
    const double hy = car.box.half.y();
    std::size_t group = kinds.size();
    for (const double dh : {-kCell, 0.0, kCell}) {
      for (const double dx : {-kCell, 0.0, kCell}) {
        for (const double dy : {-kCell, 0.0, kCell}) {
          const auto found = leaders.find(kindCell(headingKey(h + dh), hx + dx, hy + dy));
          if (found == leaders.end()) continue;
          for (const std::size_t g : found->second) {
            if (g < group && sameKind(*kinds[g].cars.front(), car)) group = g;
          }
        }
      }
    }
    if (group == kinds.size()) {
      leaders[kindCell(h, hx, hy)].push_back(kinds.size());
      kinds.push_back({{&car}});
    } else {
      kinds[group].cars.push_back(&car);
    }
  }
  return kinds;
}

// The empty slots of one row of same-kind cars (at least two), as bay centres.
std::vector<Eigen::Vector2d> emptySlots(const std::vector<const ParkedCar*>& cars) {
  // The row's line runs from the first car to its nearest neighbour.
  const Eigen::Vector2d origin = cars.front()->box.center;
  const ParkedCar* nearest = nullptr;
  for (const ParkedCar* car : cars) {
    if (car == cars.front()) continue;
    if (nearest == nullptr ||
        (car->box.center - origin).squaredNorm() < (nearest->box.center - origin).squaredNorm()) {
      nearest = car;
    }
  }
  const Eigen::Vector2d along = (nearest->box.center - origin).normalized();
  const double pitch = (nearest->box.center - origin).norm();
  std::vector<std::int64_t> steps;
  for (const ParkedCar* car : cars) {
    const Eigen::Vector2d d = car->box.center - origin;
    const double t = d.dot(along) / pitch;
    const double off_line = std::abs(d.x() * along.y() - d.y() * along.x());
    if (off_line > kSame || std::abs(t - std::round(t)) * pitch > kSame) continue;
    steps.push_back(static_cast<std::int64_t>(std::llround(t)));
  }
  std::sort(steps.begin(), steps.end());
  std::vector<Eigen::Vector2d> slots;
  if (steps.size() < 2) return slots;
  for (std::int64_t k = steps.front() - 1; k <= steps.back() + 1; ++k) {
    if (!std::binary_search(steps.begin(), steps.end(), k)) {
      slots.push_back(origin + along * (pitch * static_cast<double>(k)));
    }
  }
  return slots;
}

bool insideBounds(const Aabb2& box, const std::optional<Aabb2>& bounds) {
  if (!bounds) return true;
  return (box.min.array() >= bounds->min.array()).all() &&
         (box.max.array() <= bounds->max.array()).all();
}

bool touchesAnything(const Obb2& box, const Scene& scene) {
  for (const ParkedCar& car : scene.parked) {
    if (overlapObb2(box, car.box)) return true;
  }
  for (const Obstacle& obstacle : scene.obstacles) {
    if (collideObbPolygon(box, obstacle.polygon).hit) return true;
  }
  return false;
}

Eigen::Vector2d chainCentre(const Scene& scene) {
  if (scene.bounds) return (scene.bounds->min + scene.bounds->max) / 2.0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const ParkedCar& car : scene.parked) sum += car.box.center;
  return scene.parked.empty() ? sum
                              : Eigen::Vector2d(sum / static_cast<double>(scene.parked.size()));
}

}  // namespace

std::vector<FreeBay> findFreeBays(const Scene& scene, const BayChainSettings& settings) {
  // Rows: cars of one kind, grouped in scene order (the first car of a kind leads its group).
  const std::vector<Row> kinds = groupByKind(scene.parked);
  std::vector<ParkingBay> found;
  for (const Row& row : kinds) {
    if (row.cars.size() < 2) continue;
    const ParkedCar& model = *row.cars.front();
    for (const Eigen::Vector2d& centre : emptySlots(row.cars)) {
      ParkingBay bay;
      bay.center = centre;
      bay.heading_deg = model.heading_deg;
      bay.length = 2.0 * model.box.half.x() + settings.bay_length_margin;
      bay.width = 2.0 * model.box.half.y() + settings.bay_width_margin;
      const Obb2 box = Obb2::fromDegrees(bay.center, bay.heading_deg, bay.length, bay.width);
      const bool duplicate = std::any_of(found.begin(), found.end(), [&](const ParkingBay& b) {
        return (b.center - centre).norm() < kSame;
      });
      if (!duplicate && insideBounds(box.aabb(), scene.bounds) && !touchesAnything(box, scene)) {
        found.push_back(bay);
      }
    }
  }
  // Counter-clockwise around the centre, from the angle nearest +x below it; then the start.
  const Eigen::Vector2d centre = chainCentre(scene);
  const auto angle = [&centre](const ParkingBay& b) {
    const Eigen::Vector2d d = b.center - centre;
    const double a = std::atan2(d.y(), d.x());
    return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
  };
  std::stable_sort(found.begin(), found.end(),
                   [&](const ParkingBay& a, const ParkingBay& b) { return angle(a) < angle(b); });
  if (!found.empty()) {
    const Eigen::Vector2d start = scene.player.position;
    const auto first = std::min_element(
        found.begin(), found.end(), [&start](const ParkingBay& a, const ParkingBay& b) {
          return (a.center - start).squaredNorm() < (b.center - start).squaredNorm();
        });
    std::rotate(found.begin(), first, found.end());
  }
  std::vector<FreeBay> bays;
  for (std::size_t i = 0; i < found.size(); ++i) {
    bays.push_back({"bay-" + std::to_string(i + 1), found[i]});
  }
  return bays;
}

Goal chainGoal(const ParkingBay& bay, const BayChainSettings& settings) {
  Goal goal;
  goal.bay = bay;
  goal.position_tolerance = settings.position_tolerance;
  goal.heading_tolerance_deg = settings.heading_tolerance_deg;
  goal.either_direction = true;
  goal.hold_time = settings.hold_time;
  return goal;
}

namespace {

Goal firstGoal(const std::vector<FreeBay>& bays, const BayChainSettings& settings) {
  return chainGoal(bays.empty() ? ParkingBay{} : bays.front().bay, settings);
}

}  // namespace

BayChain::BayChain(const Scene& scene, double hz, const BayChainSettings& settings)
    : bays_(findFreeBays(scene, settings)),
      settings_(settings),
      hz_(hz),
      start_health_(scene.player.health),
      limit_frames_(static_cast<std::int64_t>(std::ceil(settings.time_limit * hz))),
      challenge_(firstGoal(bays_, settings), hz, scene.player.health) {}

std::optional<std::size_t> BayChain::current() const {
  if (bays_.empty()) return std::nullopt;
  return current_;
}

std::int64_t BayChain::clockFrames() const {
  return clock_start_ ? frame_ - *clock_start_ : 0;
}

bool BayChain::over() const {
  return bays_.empty() || timed_out_ || wrecked_;
}

double BayChain::secondsLeft() const {
  const double left = static_cast<double>(limit_frames_ - clockFrames()) / hz_;
  return std::max(0.0, left);
}

ChainScore BayChain::score() const {
  return {count_, last_park_clock_, static_cast<double>(last_park_clock_) / hz_};
}

std::optional<std::size_t> BayChain::next() const {
  if (bays_.size() < 2) return std::nullopt;
  return (current_ + 1) % bays_.size();
}

bool ChainScore::betterThan(const ChainScore& other) const {
  if (count != other.count) return count > other.count;
  return seconds < other.seconds;
}

void BayChain::observe(const World& world) {
  if (over()) return;
  if (!clock_start_ && world.car().position != world.scene().player.position) {
    clock_start_ = std::max<std::int64_t>(0, world.frame() - 1);
  }
  frame_ = world.frame();
  if (world.gameOver()) {
    wrecked_ = true;
    return;
  }
  if (clockFrames() >= limit_frames_) {
    timed_out_ = true;
    return;
  }
  challenge_.observe(world);
  if (must_leave_) {
    // Parked again without leaving: watch afresh, uncounted, until the car is out of the bay.
    if (challenge_.parkedFrame()) {
      challenge_ = ParkingChallenge(chainGoal(bays_[current_].bay, settings_), hz_, start_health_);
      challenge_.observe(world);
    }
    must_leave_ = challenge_.lastCheck().position_ok;
    return;
  }
  if (challenge_.parkedFrame()) {
    ++count_;
    last_park_clock_ = clockFrames();
    current_ = (current_ + 1) % bays_.size();
    must_leave_ = bays_.size() == 1;
    challenge_ = ParkingChallenge(chainGoal(bays_[current_].bay, settings_), hz_, start_health_);
    if (must_leave_) challenge_.observe(world);
  }
}

}  // namespace cardemo
