#pragma once
/// Free drive with a purpose: the free bays of a lot (the empty slots of its rows of parked cars),
/// highlighted one at a time; each parked bay adds one to the count and highlights the next. It
/// judges each bay with the levels' goal code (ParkingChallenge) and, like it, only observes the
/// World, so a replay of the drive reproduces the count.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/parking_goal.hpp"
#include "sim/scene.hpp"

namespace cardemo {

class World;

/// An empty slot of a row of parked cars, where the player can park.
struct FreeBay {
  std::string id;  ///< "bay-1", "bay-2", ... in chain order.
  ParkingBay bay;  ///< The slot, sized for the row's cars with room around them.
};

/// The rules of the bay chain.
struct BayChainSettings {
  double bay_length_margin = 1.0;     ///< The bay is this much longer than the row's cars, m.
  double bay_width_margin = 0.8;      ///< and this much wider, m.
  double position_tolerance = 0.6;    ///< As a level's goal, m.
  double heading_tolerance_deg = 10;  ///< As a level's goal, degrees (either way round counts).
  double hold_time = 0.5;             ///< Seconds the car must stand parked, as in the levels.
  double time_limit = 180.0;          ///< The chain ends after this long on its clock, s.
};

/// The free bays of `scene`, in chain order. A row is two or more parked cars of the same size and
/// heading whose centres lie on one line at multiples of one pitch (the smallest gap between
/// neighbours); its slots run from one pitch before its first car to one pitch past its last, and
/// each slot with no car is a bay unless the bay would reach past the bounds or touch a car or an
/// obstacle. Chain order runs counter-clockwise around the centre of the bounds (of the parked
/// cars without bounds), starting at the bay nearest the player's start.
[[nodiscard]] std::vector<FreeBay> findFreeBays(const Scene& scene,
                                                const BayChainSettings& settings = {});

/// The goal for parking in `bay` under `settings`: no par, no time limit of its own.
[[nodiscard]] Goal chainGoal(const ParkingBay& bay, const BayChainSettings& settings);

/// The result of a bay chain: how many bays, and when the last of them was parked.
struct ChainScore {
  int count = 0;            ///< Bays parked.
  std::int64_t frames = 0;  ///< Frames on the chain's clock when the last of them was parked.
  double seconds = 0.0;     ///< frames / hz.

  /// True when this score beats `other`: more bays, then the last of them sooner.
  [[nodiscard]] bool betterThan(const ChainScore& other) const;
};

/// The bay chain run beside a World: call observe() on frame 0 and after every step.
class BayChain {
 public:
  /// A chain over the free bays of `scene`, at `hz` steps a second.
  BayChain(const Scene& scene, double hz, const BayChainSettings& settings = {});

  /// Looks at the world's current frame: counts the highlighted bay once the car is parked in it
  /// and highlights the next. Does nothing once the chain is over.
  void observe(const World& world);

  /// The free bays, in chain order (empty: the scene has none, and the chain is over at once).
  [[nodiscard]] const std::vector<FreeBay>& bays() const { return bays_; }
  /// Index in bays() of the highlighted bay, or nullopt when there is none.
  [[nodiscard]] std::optional<std::size_t> current() const;
  /// Bays parked so far.
  [[nodiscard]] int count() const { return count_; }
  /// Frames on the chain's clock, which starts when the car first moves (as a level's clock).
  [[nodiscard]] std::int64_t clockFrames() const;
  /// The frame at which the chain's clock started, once the car has moved.
  [[nodiscard]] std::optional<std::int64_t> clockStart() const { return clock_start_; }
  /// Seconds left before the time limit ends the chain (0 once it has).
  [[nodiscard]] double secondsLeft() const;
  /// The time limit passed, the car was wrecked, or there is no bay: the count is final.
  [[nodiscard]] bool over() const;
  /// The time limit ended the chain.
  [[nodiscard]] bool timedOut() const { return timed_out_; }
  /// Health reached 0 and ended the chain.
  [[nodiscard]] bool wrecked() const { return wrecked_; }
  /// The count so far and the clock when its last bay was parked.
  [[nodiscard]] ChainScore score() const;
  /// Index in bays() of the bay after the highlighted one, or nullopt with fewer than two bays.
  [[nodiscard]] std::optional<std::size_t> next() const;
  /// The rules the chain runs by.
  [[nodiscard]] const BayChainSettings& settings() const { return settings_; }
  /// Steps per second.
  [[nodiscard]] double hz() const { return hz_; }
  /// The goal check of the highlighted bay (the readout and hold of the levels).
  [[nodiscard]] const ParkingChallenge& challenge() const { return challenge_; }

 private:
  std::vector<FreeBay> bays_;
  BayChainSettings settings_;
  double hz_;
  int start_health_;
  std::size_t current_ = 0;
  int count_ = 0;
  std::int64_t limit_frames_;
  std::optional<std::int64_t> clock_start_;
  std::int64_t frame_ = 0;
  std::int64_t last_park_clock_ = 0;
  bool timed_out_ = false;
  bool wrecked_ = false;
  // With a single bay the next bay is the one just parked: it counts again only after the car
  // has left it, or standing still would count it every hold time.
  bool must_leave_ = false;
  ParkingChallenge challenge_;
};

}  // namespace cardemo
