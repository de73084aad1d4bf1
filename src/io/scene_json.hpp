#pragma once
/// Scene files (JSON, `cardemo-scene/1`): strict parse and validation with line numbers.

#include <string>
#include <string_view>

#include "io/input_error.hpp"
#include "sim/scene.hpp"

namespace cardemo {

/// Largest scene file accepted, bytes.
inline constexpr std::size_t kMaxSceneBytes = 512u << 20;

/// Parses scene JSON text. `filename` is used in error messages only. Every error names the line
/// and the field (e.g. `lot.json:7: parked[2].width: must be finite and > 0`). Unknown keys,
/// NaN/inf, nesting deeper than 64, duplicate ids and non-convex obstacles are errors.
[[nodiscard]] Parsed<Scene> parseScene(std::string_view text, const std::string& filename);

/// Reads and parses a scene file.
[[nodiscard]] Parsed<Scene> loadScene(const std::string& path);

}  // namespace cardemo
