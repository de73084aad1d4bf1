#pragma once
/// A goal's gates passed in order, from the path of the car's centre between steps.
///
/// The rule (docs/formats.md): each step's path is the closed segment from the car's centre
/// before the step to its centre after it. A line gate is crossed on a step that ends strictly on
/// the other side of the gate's line than the centre last strictly was, when that step's path
/// meets the closed gate segment (its end points count); touching the line and turning back is
/// no crossing. A box gate is passed on a step whose path meets the closed box. With a direction,
/// a line must be crossed towards that side and a box entered while moving along the direction
/// (the step advances along it). All tests are exact (geometry/exact_sign).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sim/scene.hpp"

namespace cardemo {

/// The largest number of gates a goal may have.
inline constexpr std::size_t kMaxGates = 64;

/// One step's path against one gate.
enum class GateCrossing : std::uint8_t {
  kNone,      ///< The path does not pass the gate.
  kPassed,    ///< Passed (the right way, when the gate has a direction).
  kWrongWay,  ///< Crossed or entered against the gate's direction.
};

/// What happened at a gate on some frame, for messages.
struct GateNotice {
  /// What the player is told.
  enum class Kind : std::uint8_t {
    kPassed,    ///< "gate N passed".
    kMissed,    ///< A later gate was passed first: "missed gate N: NAME" (N the one skipped).
    kWrongWay,  ///< The next gate was crossed the wrong way.
  };
  Kind kind = Kind::kPassed;  ///< What happened.
  std::size_t gate = 0;       ///< 0-based index of the gate named.
  std::int64_t frame = 0;     ///< Frame of the step.
};

/// How a step's path from `p0` to `p1` passes `gate`. For a line gate `last_side` is the side
/// (+1 left of from -> to, -1 right) the centre was last strictly on (0: never yet) and is
/// updated to p1's side when p1 is off the line.
[[nodiscard]] GateCrossing crossGate(const Gate& gate, const Eigen::Vector2d& p0,
                                     const Eigen::Vector2d& p1, int& last_side);

/// The side (+1 left, -1 right, 0 on it) of `p` against a line gate's from -> to.
[[nodiscard]] int gateSide(const Gate& gate, const Eigen::Vector2d& p);

/// The gates of a goal, passed in order: observe the car's centre at frame 0 (start) and after
/// every step (step). Never allocates after construction.
class GateCourse {
 public:
  /// A course over a copy of `gates`.
  explicit GateCourse(std::vector<Gate> gates = {});

  /// The centre at the first frame observed.
  void start(const Eigen::Vector2d& position);
  /// The step to `frame` moved the centre from `from` to `to`.
  void step(const Eigen::Vector2d& from, const Eigen::Vector2d& to, std::int64_t frame);

  /// Number of gates.
  [[nodiscard]] std::size_t size() const { return gates_.size(); }
  /// Gates passed so far (the first passed() of them, in order).
  [[nodiscard]] std::size_t passed() const { return next_; }
  /// Every gate is passed: the bay counts.
  [[nodiscard]] bool done() const { return next_ == gates_.size(); }
  /// The gate to pass next, or null when done.
  [[nodiscard]] const Gate* nextGate() const { return done() ? nullptr : &gates_[next_]; }
  /// Frame at which gate `i` was passed, if it is.
  [[nodiscard]] std::optional<std::int64_t> passedFrame(std::size_t i) const;
  /// The latest notice (pass, miss or wrong way), if any.
  [[nodiscard]] const std::optional<GateNotice>& lastNotice() const { return last_notice_; }
  /// How many steps passed a later gate before the next one.
  [[nodiscard]] std::int64_t misses() const { return misses_; }
  /// The latest miss, if any.
  [[nodiscard]] const std::optional<GateNotice>& lastMiss() const { return last_miss_; }
  /// The gates.
  [[nodiscard]] std::span<const Gate> gates() const { return gates_; }

 private:
  std::vector<Gate> gates_;
  std::vector<int> sides_;                   // per gate: the side its line last strictly had
  std::vector<GateCrossing> crossings_;      // per gate: this step's result (scratch)
  std::vector<std::int64_t> passed_frames_;  // per passed gate, in order
  std::size_t next_ = 0;
  std::int64_t misses_ = 0;
  std::optional<GateNotice> last_notice_;
  std::optional<GateNotice> last_miss_;
};

}  // namespace cardemo
