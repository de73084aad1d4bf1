#pragma once
/// A replay run headless exactly like `cardemo replay`, compared frame by frame.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/frame_compare.hpp"
#include "io/input_error.hpp"

namespace cardemo::compare {

/// A finished comparison with what the report needs about the run.
struct ReplayComparison {
  CompareReport report;       ///< Counts, hits, examples.
  std::string scene_name;     ///< The scene's name.
  std::size_t colliders = 0;  ///< Parked cars plus obstacles in the scene.
  std::size_t walls = 0;      ///< Walls of the scene's bounds checked too (4, or 0 without bounds).
};

/// Loads the replay and its scene (`scene_override` wins when non-empty), runs every input frame
/// and compares frame 0 and every step. Bad input is returned as an error, like `cardemo replay`.
/// `on_loaded` (when set) hears the collider count before the run starts.
[[nodiscard]] Parsed<ReplayComparison> compareReplay(
    const std::string& replay_path, const std::string& scene_override,
    const CompareOptions& options, const std::function<void(std::size_t)>& on_loaded = {});

/// The contract's comparison JSON plus the extension fields (see docs/box2d-comparison.md).
[[nodiscard]] nlohmann::json comparisonJson(const CompareReport& report);

/// Human-readable table and the first disagreements, one screen.
[[nodiscard]] std::string comparisonText(const ReplayComparison& comparison);

/// Hits of `v` that exact does not have plus exact hits `v` lacks.
[[nodiscard]] std::size_t hitDifferences(const CompareReport& report, Verdict v);

}  // namespace cardemo::compare
