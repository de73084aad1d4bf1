// The page's entry points: page.js calls cardemo_start once the files are in place, then the
// browser's frames drive WebApp through emscripten_set_main_loop, and its key events reach it.

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <memory>
#include <optional>

#include "web/web_app.hpp"
#include "web/web_keys.hpp"

// clang-format off
EM_JS(void, cardemo_frame_time, (double ms, double update, double draw, double flush), {
  Module.page.frameTime(ms, update, draw, flush);
});
// clang-format on

namespace {

using cardemo::GameKey;

std::unique_ptr<cardemo::WebApp> app;
double last_frame_ms = 0.0;

std::optional<GameKey> keyOf(const EmscriptenKeyboardEvent& e) {
  if (std::optional<GameKey> key = cardemo::gameKeyOfSymbol(e.key)) return key;
  return cardemo::gameKeyOfCode(e.code);
}

// Returns true (the browser does nothing more with the key) for the keys the game reads, so the
// arrows and Space do not scroll the page and F1 does not open the browser's help.
EM_BOOL onKey(int type, const EmscriptenKeyboardEvent* e, void*) {
  const std::optional<GameKey> key = keyOf(*e);
  if (!key || !app) return EM_FALSE;
  app->key(*key, type == EMSCRIPTEN_EVENT_KEYDOWN, e->repeat != 0);
  return EM_TRUE;
}

EM_BOOL onBlur(int, const EmscriptenFocusEvent*, void*) {
  if (app) app->blur();
  return EM_FALSE;
}

void frame() {
  const double now = emscripten_get_now();
  const double elapsed = last_frame_ms > 0.0 ? (now - last_frame_ms) / 1000.0 : 0.0;
  last_frame_ms = now;
  app->frame(elapsed);
  // Update plus draw (the batch handed to the canvas), for the page's frame-time figures.
  const cardemo::FrameParts& parts = app->lastFrameParts();
  cardemo_frame_time(emscripten_get_now() - now, parts.update, parts.draw, parts.flush);
}

}  // namespace

extern "C" {

/// Starts the game: the picker, or the replay at `replay_path` when it is not empty (to its end at
/// once when `to_the_end` is not 0).
EMSCRIPTEN_KEEPALIVE void cardemo_start(const char* replay_path, int to_the_end) {
  app = std::make_unique<cardemo::WebApp>(cardemo::WebPaths{});
  if (replay_path[0] != '\0') app->watch(replay_path, to_the_end != 0);
  const char* window = EMSCRIPTEN_EVENT_TARGET_WINDOW;
  emscripten_set_keydown_callback(window, nullptr, EM_FALSE, onKey);
  emscripten_set_keyup_callback(window, nullptr, EM_FALSE, onKey);
  emscripten_set_blur_callback(window, nullptr, EM_FALSE, onBlur);
  emscripten_set_main_loop(frame, 0, 0);
}

/// Watches the replay at `path` (a file the page wrote, e.g. one opened from disk).
EMSCRIPTEN_KEEPALIVE void cardemo_watch(const char* path, int to_the_end) {
  if (app) app->watch(path, to_the_end != 0);
}

}  // extern "C"
