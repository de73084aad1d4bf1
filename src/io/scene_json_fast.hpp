#pragma once
/// The fast scene reader (private to io/, built with simdjson): parses straight into a Scene with
/// no tree and no line numbers. It accepts exactly the scenes the line-tracking reader accepts,
/// with the same values; it only says no, and parseScene then asks the line-tracking reader why.

#include <optional>
#include <string>

#include "io/padded_text.hpp"
#include "sim/scene.hpp"

namespace cardemo {

/// The scene in `text`, or nullopt when it is not a valid scene (or memory ran out). `filename`
/// names a scene without a `name`.
[[nodiscard]] std::optional<Scene> parseSceneFast(const PaddedText& text,
                                                  const std::string& filename);

}  // namespace cardemo
