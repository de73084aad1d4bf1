#pragma once
/// The line-tracking scene reader (private to io/): reads the JSON into a tree that remembers
/// every value's line, then validates it field by field. Slow, but every error it returns names
/// the line and the field; parseScene calls it when the fast reader turns a file down.

#include <string>
#include <string_view>

#include "io/input_error.hpp"
#include "sim/scene.hpp"

namespace cardemo {

/// Parses scene JSON text as parseScene documents, with the exact `FILE:LINE: message` errors.
[[nodiscard]] Parsed<Scene> parseSceneWithLines(std::string_view text, const std::string& filename);

}  // namespace cardemo
