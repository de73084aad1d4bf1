#pragma once
/// The same replay run as a Box2D 2.4.1 b2World, to show what a b2World user would see instead.

#include <cstdint>
#include <string>
#include <vector>

#include "io/input_error.hpp"

namespace cardemo::compare {

/// A first contact with one static collider.
struct WorldContact {
  std::int64_t frame = 0;      ///< Our frame number (the b2World step run right after it).
  std::uint32_t collider = 0;  ///< Index: parked cars first, then obstacles.
  std::string id;              ///< The collider's id.
  double b2_offset = 0.0;      ///< |b2World body centre - our car centre| at that frame, metres.
};

/// How close b2World's body came to a collider it touched, after the begin-contact event.
struct WorldGap {
  std::string id;           ///< The collider's id.
  double min_gap = 0.0;     ///< Smallest polygon-to-polygon distance b2World left, metres.
  std::int64_t frames = 0;  ///< Frames measured (from begin contact to the end).
};

/// Everything `cardemo compare-world` reports.
struct WorldComparison {
  std::string scene_name;                  ///< The scene's name.
  double hz = 0.0;                         ///< Steps per second.
  std::int64_t frames = 0;                 ///< Steps run.
  std::size_t colliders = 0;               ///< Parked cars plus obstacles.
  std::vector<WorldContact> ours;          ///< Our hits.
  std::vector<WorldContact> b2;            ///< b2World BeginContact events.
  std::vector<WorldGap> gaps;              ///< Per collider b2World touched.
  double end_offset = 0.0;                 ///< Body-to-car distance after the last step, metres.
  double max_offset = 0.0;                 ///< Largest body-to-car distance over the run, metres.
  double our_speed_step1 = 0.0;            ///< Our |velocity| after step 1, m/s.
  double b2_speed_step1 = 0.0;             ///< b2World body's |velocity| after step 1, m/s.
  double speed_limit = 0.0;                ///< b2_maxTranslation * hz, m/s.
  std::int64_t clamped_steps = 0;          ///< Steps where b2World's speed fell below ours by > 1%.
  std::int64_t touching_static_pairs = 0;  ///< Static-static pairs within Box2D's skin.
};

/// Loads the replay and its scene (`scene_override` wins when non-empty), runs our World and a
/// b2World driven by our car's velocity side by side. Bad input is an error, as in `cardemo
/// replay`.
[[nodiscard]] Parsed<WorldComparison> compareWorld(const std::string& replay_path,
                                                   const std::string& scene_override);

/// The plain-text report.
[[nodiscard]] std::string worldComparisonText(const WorldComparison& comparison);

}  // namespace cardemo::compare
