#include "io/scene_json.hpp"

#include <optional>
#include <utility>

#include "io/scene_json_lines.hpp"

#if CARDEMO_WITH_SIMDJSON
#include "io/padded_text.hpp"
#include "io/scene_json_fast.hpp"
#endif

namespace cardemo {

// With simdjson the fast reader goes first, and only a file it turns down is read again by the
// line-tracking reader, whose answer (and error message) is the same with or without simdjson.
Parsed<Scene> parseScene(std::string_view text, const std::string& filename) {
#if CARDEMO_WITH_SIMDJSON
  if (std::optional<Scene> scene = parseSceneFast(PaddedText::copyOf(text), filename)) {
    return std::move(*scene);
  }
#endif
  return parseSceneWithLines(text, filename);
}

Parsed<Scene> loadScene(const std::string& path) {
#if CARDEMO_WITH_SIMDJSON
  Parsed<PaddedText> text = readPaddedFile(path, kMaxSceneBytes);
  if (!text.ok()) return text.error();
  if (std::optional<Scene> scene = parseSceneFast(text.value(), path)) return std::move(*scene);
  return parseSceneWithLines(text.value().view(), path);
#else
  Parsed<std::string> text = readInputFile(path, kMaxSceneBytes);
  if (!text.ok()) return text.error();
  return parseSceneWithLines(text.value(), path);
#endif
}

}  // namespace cardemo
