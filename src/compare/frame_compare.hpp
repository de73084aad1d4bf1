#pragma once
/// Frame-by-frame comparison: the player's box against every static collider, judged every way.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/pair_verdicts.hpp"
#include "sim/world.hpp"

namespace cardemo::compare {

/// Borderline disagreements kept per verdict (they explain hit-list differences).
inline constexpr std::size_t kMaxBorderline = 10000;

/// Options of a comparison.
struct CompareOptions {
  std::optional<double> radius;   ///< Only colliders whose AABB is within this of the player's, m.
  bool all_exact = false;         ///< Run the GMP oracle on every pair (no shortcut).
  std::size_t max_examples = 10;  ///< Disagreements kept per verdict, for the report.
};

/// Counts of one verdict against the exact one.
struct Tally {
  std::int64_t agree = 0;       ///< Same verdict as exact.
  std::int64_t disagree = 0;    ///< Different, with |exact separation| > kBorderline.
  std::int64_t borderline = 0;  ///< Different, within kBorderline of touching.
};

/// A first contact implied by a verdict: false at the previous frame (or frame 0), true now.
struct FirstContact {
  std::int64_t frame = 0;      ///< Frame.
  std::uint32_t collider = 0;  ///< Collider index (parked cars, then obstacles, then walls).
  friend bool operator==(const FirstContact&, const FirstContact&) = default;
};

/// A disagreement outside the tolerance.
struct Disagreement {
  std::int64_t frame = 0;         ///< Frame.
  std::uint32_t collider = 0;     ///< Collider index.
  bool verdict = false;           ///< What the verdict said (exact said the opposite).
  double exact_separation = 0.0;  ///< Exact separation, metres.
};

/// Everything recorded for one verdict.
struct VerdictRecord {
  Tally tally;                                 ///< Against exact (exact's own is all agree).
  std::vector<FirstContact> hits;              ///< First-contact frames, in order.
  std::vector<Disagreement> examples;          ///< The first few disagreements.
  std::vector<Disagreement> borderline_pairs;  ///< Borderline disagreements (first kMaxBorderline).
};

/// Result of a comparison run.
struct CompareReport {
  std::int64_t frames = 0;         ///< Frames simulated (frame 0 is checked too).
  std::int64_t pairs_checked = 0;  ///< Player-collider pairs judged, over all frames.
  std::int64_t gmp_calls = 0;      ///< Pairs that needed the GMP oracle.
  std::array<VerdictRecord, kVerdictCount> verdicts;  ///< Indexed by Verdict.
  std::vector<std::string> ids;  ///< Collider ids by index; then the walls' (bounds-west, ...).
  std::optional<double> radius;  ///< The --radius in force, if any.

  /// The record of one verdict.
  [[nodiscard]] const VerdictRecord& operator[](Verdict v) const {
    return verdicts[static_cast<std::size_t>(v)];
  }
  /// Mutable record of one verdict.
  [[nodiscard]] VerdictRecord& operator[](Verdict v) {
    return verdicts[static_cast<std::size_t>(v)];
  }
};

/// Exit status of `cardemo compare`: 1 when cardemo's verdict disagrees with the exact oracle
/// outside the tolerance (a failed check), else 0; Box2D's disagreements are findings, not
/// failures.
[[nodiscard]] int compareExitStatus(const CompareReport& report);

/// Checks one world's frames as they happen; construct at frame 0, call check() after each step.
class FrameComparer {
 public:
  /// Builds the Box2D shapes of every collider and checks frame 0.
  FrameComparer(const World& world, const CompareOptions& options);
  /// Checks the world's current frame.
  void check(const World& world);
  /// The report so far (frames = the last frame checked).
  [[nodiscard]] const CompareReport& report() const { return report_; }

 private:
  CompareOptions options_;
  CompareReport report_;
  std::vector<Box2dPair> shapes_;
  std::vector<Box2dWall> walls_;  // Box2D's edges of the scene's walls (none without bounds)
  Box2dPair player_;
  // Per verdict and collider: the last frame at which the verdict was true (-2: never).
  std::array<std::vector<std::int64_t>, kVerdictCount> last_true_;

  void record(std::int64_t frame, std::uint32_t collider, const PairVerdicts& v);
};

}  // namespace cardemo::compare
