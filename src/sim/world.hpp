#pragma once
/// The simulation: one player car among static cars, advanced in fixed steps.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collision/broad_phase.hpp"
#include "collision/narrow_phase.hpp"
#include "collision/static_colliders.hpp"
#include "sim/car.hpp"
#include "sim/contact_response.hpp"
#include "sim/crash_ledger.hpp"
#include "sim/driver_controls.hpp"
#include "sim/input_frame.hpp"
#include "sim/scene.hpp"
#include "sim/simulation_schemes.hpp"
#include "sim/walls.hpp"

namespace cardemo {

/// World settings; defaults are the game's.
struct WorldSettings {
  double hz = 120.0;    ///< Fixed steps per second.
  CarParams car;        ///< Car tuning (length/width come from the scene).
  int damage_min = 3;   ///< Damage of the gentlest hit that does damage at all.
  int damage_max = 50;  ///< Damage of the hardest hit.
  double damage_per_mps =
      3.0;  ///< Damage per m/s of normal impact speed (rounded up, ignoring an excess below 1e-9).
  double damage_threshold = 1.0;  ///< Hits closing slower than this (m/s) do no damage.
  double crash_window = 1.5;      ///< A re-touch of the same collider within this many seconds of
                                  ///< the last contact with it is the same crash, s.
  double scrape_threshold = 1.0;  ///< Sliding along a collider faster than this (m/s) scrapes.
  double scrape_damage_per_s = 4.0;  ///< Damage per second of scraping (whole points, exact).
  int max_push_iterations = 4;       ///< Contact resolution passes per step.
  double seam_depth = 0.05;  ///< A new contact that overlaps by at most this much (m) along the
                             ///< normal of a collider touched at the last frame takes that normal:
                             ///< the seam between two neighbours is not a wall.
  double corner_slip_depth = 0.2;  ///< A head-on contact that a sideways push of at most this
                                   ///< much (m) clears is a clipped corner: the car slides past.
  SimulationSchemes schemes;       ///< Alternatives for studies; the defaults are the game's.
};

/// A hit: the first frame of contact with one static collider.
struct HitEvent {
  std::int64_t frame = 0;      ///< Frame at which contact began.
  std::uint32_t collider = 0;  ///< Index: parked cars first, then obstacles, then the walls.
  std::string id;              ///< The collider's id (a wall's: wallId).
  double speed = 0.0;          ///< Closing speed along the contact normal at impact, m/s.
  int damage = 0;              ///< Health taken: 0 below the threshold or when the crash it
                               ///< belongs to already charged as much.
  std::int64_t crash = 0;      ///< The crash (1, 2, ...) this hit belongs to: re-touches of the
                               ///< same collider within the crash window share one.
};

/// Work done so far (the summary's `stats`).
struct WorldStats {
  std::int64_t broadphase_queries = 0;     ///< Grid queries actually run.
  std::int64_t broadphase_candidates = 0;  ///< Candidates sent to the narrow phase, summed.
  std::int64_t narrowphase_tests = 0;      ///< SAT tests run.
  /// Candidates whose SAT test was skipped after a push-out: their separation before the push
  /// exceeded the distance pushed (SimulationSchemes::translation_bound).
  std::int64_t skipped_tests = 0;
  std::int64_t contacts = 0;  ///< Frames x colliders in contact, summed.
  std::int64_t substeps = 0;  ///< Extra collision sub-steps (turning fast, or a study's scheme).
  /// Detections skipped (a step detects once or more): the player's box was the last detected.
  std::int64_t skipped_queries = 0;
  /// Queries answered from the last grid query's grown box instead of the grid (the candidates
  /// are the same).
  std::int64_t reused_queries = 0;
  std::int64_t sweeps = 0;             ///< Swept SAT tests run (continuous mode, fast steps only).
  std::int64_t broadphase_builds = 0;  ///< Times the broad-phase structure was built (once).
  std::int64_t resting_steps = 0;  ///< Steps skipped whole: at rest, same input as the step before.
};

/// A contact of the current frame (for the debug overlay and the trace).
struct ActiveContact {
  std::uint32_t collider = 0;                         ///< Collider index (walls after the rest).
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< From the player to the collider.
  double separation = 0.0;                            ///< Before push-out, metres (<= 0).
  bool slipped = false;  ///< A clipped corner the car was pushed sideways past (slipPastCorner).
};

class World;

/// A step's motion as a MotionScheme drives it (SimulationSchemes::motion): the player's car placed
/// at poses along the step, each tested for contact. Only World makes one, during its step.
class StepMotion {
 public:
  /// Places the car at `pose` and detects contacts there; true when it touches anything.
  bool detectAt(const CarState& pose);
  /// The game's scheme: the motion swept to the first time of impact where the step is fast.
  /// Returns the fraction of the step at which contact was found (1: at the end pose, or none).
  double continuous(const CarState& start, const CarState& next);
  /// Counts `n` extra collision sub-steps (WorldStats::substeps).
  void countSubsteps(std::int64_t n);
  /// Half the car's smaller side, metres: the motion that can pass nothing.
  [[nodiscard]] double halfMinExtent() const;
  /// The fixed step, seconds.
  [[nodiscard]] double dt() const;

 private:
  friend class World;
  explicit StepMotion(World& world) : world_(world) {}
  World& world_;
};

/// The world: owns the scene, the broad phase (built once) and the player's car.
class World {
 public:
  /// Builds the broad phase over the scene's static colliders and places the player (frame 0;
  /// contacts already present at frame 0 are hits at frame 0).
  World(Scene scene, const WorldSettings& settings = {});

  /// Advances one fixed step: integrate; then, when the motion exceeds half the car's smaller
  /// extent, sweep it to the first time of impact (or a study's scheme, per settings); broad phase,
  /// narrow phase on the candidates, push-out and velocity response, walls, then hits and health.
  /// Never allocates once warmed up and never throws.
  void step(const InputFrame& input);

  /// Frames simulated so far (0 after construction).
  [[nodiscard]] std::int64_t frame() const { return frame_; }
  /// The player's car.
  [[nodiscard]] const CarState& car() const { return car_; }
  /// The player's box.
  [[nodiscard]] Obb2 carBox() const;
  /// The input applied at the last step (all keys up once the game is over, or before any step).
  [[nodiscard]] const InputFrame& lastInput() const { return last_input_; }
  /// The driver's state after the last step: each pedal's press, the steering key's hold.
  [[nodiscard]] const DriverControls& controls() const { return controls_; }
  /// The gear: D moving forward or with the throttle driving, R moving backward or with Down
  /// driving backward, N at a standstill otherwise (gearOf).
  [[nodiscard]] Gear gear() const { return gearOf(car_.speed, controls_); }
  /// The wheel angle (radians) the next step would give the car with `keys` held: what a
  /// controller steering in proportion aims with.
  [[nodiscard]] double steerAfter(const InputFrame& keys) const;
  /// The car's parameters in force (the settings' with the scene's body and speed cap).
  [[nodiscard]] const CarParams& carParams() const { return params_; }
  /// The car's lateral slip speed, m/s, positive to the left of its heading.
  [[nodiscard]] double slipSpeed() const { return car_.slip; }
  /// True when the tyres slide (skid marks, screech): lateral slip above `CarParams::skid_slip`,
  /// turning at the grip limit, or the handbrake locking moving wheels.
  [[nodiscard]] bool sliding() const { return sliding_; }
  /// True when the last step's input slowed a moving car (brake, throttle against a reverse roll,
  /// both pedals, or the handbrake): the brake lights.
  [[nodiscard]] bool braking() const { return braking_; }
  /// True when the car moves backwards: the reversing lights.
  [[nodiscard]] bool reversing() const { return car_.speed < 0.0; }
  /// Current health, never below 0.
  [[nodiscard]] int health() const { return health_; }
  /// True once health has reached 0 (input is ignored from then on).
  [[nodiscard]] bool gameOver() const { return health_ <= 0; }
  /// Health taken by scraping so far.
  [[nodiscard]] int scrapeDamage() const { return ledger_.scrapeDamage(); }
  /// Crashes so far (a crash is one or more hits of one collider, see HitEvent::crash).
  [[nodiscard]] std::int64_t crashes() const { return ledger_.crashes(); }
  /// Crashes that cost health: each counts once, from its first hit with damage (a touch under
  /// the damage threshold, or a bounce inside a crash already charged, adds none).
  [[nodiscard]] std::int64_t damagingCrashes() const { return ledger_.damagingCrashes(); }
  /// Every hit so far, in order.
  [[nodiscard]] const std::vector<HitEvent>& hits() const { return hits_; }
  /// Contacts at the current frame.
  [[nodiscard]] const std::vector<ActiveContact>& contacts() const { return contacts_; }
  /// Broad-phase candidates of the last query (for the debug overlay).
  [[nodiscard]] const std::vector<std::uint32_t>& candidates() const { return candidates_; }
  /// Work counters.
  [[nodiscard]] const WorldStats& stats() const { return stats_; }
  /// The scene as loaded.
  [[nodiscard]] const Scene& scene() const { return scene_; }
  /// Settings in force.
  [[nodiscard]] const WorldSettings& settings() const { return settings_; }
  /// Static colliders: parked cars (as Obb2) then obstacles, in scene order.
  [[nodiscard]] const StaticColliders& colliders() const { return colliders_; }
  /// The id of collider i; from colliders().size() on, the walls' (kWallSides order, wallId).
  [[nodiscard]] const std::string& colliderId(std::uint32_t i) const;
  /// True when index `i` (of a hit or contact) is a wall of the scene's bounds.
  [[nodiscard]] bool isWall(std::uint32_t i) const { return i >= colliders_.size(); }
  /// The index a wall's hits and contacts carry.
  [[nodiscard]] std::uint32_t wallIndex(WallSide side) const {
    return static_cast<std::uint32_t>(colliders_.size()) + static_cast<std::uint32_t>(side);
  }
  /// 64-bit FNV-1a over the exact bits of the state, field by field (see docs/formats.md).
  [[nodiscard]] std::uint64_t stateHash() const;

 private:
  friend class StepMotion;

  Scene scene_;
  WorldSettings settings_;
  CarParams params_;
  StaticColliders colliders_;
  UniformGrid grid_;
  CarState car_;
  int health_ = 100;
  std::int64_t frame_ = 0;
  InputFrame last_input_;
  DriverControls controls_;
  bool sliding_ = false;
  bool braking_ = false;
  std::vector<HitEvent> hits_;
  std::vector<ActiveContact> contacts_;
  std::vector<std::uint32_t> candidates_;
  // Entry k, for each candidates_[k] after a narrow phase: a lower bound on its separation from
  // detected_.box, metres (the SAT separation, or for a skipped test the bound carried over). It
  // can be longer than candidates_; the entries past it are unused.
  std::vector<double> candidate_gaps_;
  // detectAfterPush's scratch: the candidates before the push, and their gaps.
  std::vector<std::uint32_t> pushed_ids_;
  std::vector<double> pushed_gaps_;
  double verdict_scale_ = 0.0;  // largest |coordinate| of the colliders' bounds, for the margin
  CrashLedger ledger_;          // touching flags, crash windows and charges, scrape damage
  // The last grid query: it ran on `box`, the query box grown by kCoverMargin, and found `ids` (in
  // id order). A query box inside it is answered from `ids` (gatherCandidates).
  struct GridCover {
    Aabb2 box;
    bool valid = false;
    QueryIds ids;
  };
  GridCover cover_;
  WorldStats stats_;

  // Per-step scratch (reserved once, so step() does not allocate when warm).
  std::vector<ActiveContact>
      previous_contacts_;              // last frame's contacts_, to clear their touching flags
  std::vector<double> contact_speed_;  // closing speed of contacts_[k] when first detected
  // The last narrow phase (detect()): the contacts at the current pose, the player box and tight
  // bounds they belong to, and whether it has run since the candidates were last replaced.
  struct Detection {
    std::vector<ActiveContact> contacts;
    Obb2 box;
    Aabb2 bounds;
    bool valid = false;
  };
  Detection detected_;
  double half_min_extent_ = 0.0;  // half the car's smaller side: the fast-motion bound, m
  double half_diagonal_ = 0.0;    // centre-to-corner distance, m
  bool resting_ =
      false;  // the last step left the car bitwise where it was, at rest, touching nothing

  void detect();
  // Detects after a push-out that translated the car by at most `pushed` metres (rounding aside)
  // since the last narrow phase: candidates whose gap then exceeded that are not tested again.
  void detectAfterPush(double pushed);
  void narrowPhase(const Obb2& box, const Aabb2& bounds);
  // narrowPhase after a translation by at most `moved` (rounding included) since the last one.
  void narrowPhaseAfterPush(const Obb2& box, const Aabb2& bounds, double moved);
  // Starts a narrow phase over candidates_ and returns the array for their gaps.
  double* beginNarrowPhase(const Aabb2& bounds);
  // Tests one candidate at `box`: stores its gap and, when it touches, adds the contact.
  void testCandidate(const Obb2& box, std::uint32_t id, double& gap);
  bool smoothSeam(const Obb2& box, std::uint32_t id, SatResult2& r) const;
  bool slipPastCorner(const Obb2& box, std::uint32_t id, SatResult2& r) const;
  void dropClearedSlips();
  void gatherCandidates(const Aabb2& query);
  void mergeDetected();
  // The game's motion scheme; returns the fraction of the step at which contact was found.
  double moveContinuous(const CarState& start, const CarState& next);
  // Where a sweep first meets a candidate: the fraction of the motion to stop at, and the time of
  // impact (the earliest over the candidates, each in [0, 1]).
  struct SweptContact {
    double stop;
    double toi;
  };
  [[nodiscard]] std::optional<SweptContact> sweepToFirstContact(
      const Obb2& box, const Obb2& end_box, const Eigen::Vector2d& displacement);
  void resolveContacts();
  // Adds the walls `walls` says the car touches to contacts_.
  void addWallContacts(const WallResponse& walls);
  void recordHits();
  [[nodiscard]] int impactDamage(double speed) const;
  void chargeScrape();
  [[nodiscard]] Eigen::Vector2d surfaceNormal() const;
};

/// Formats a hash as 16 lowercase hex digits.
[[nodiscard]] std::string hashHex(std::uint64_t hash);

}  // namespace cardemo
