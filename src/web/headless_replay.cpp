// The page's headless replay, for the benchmark against native (tests/web/page-bench.js): the same
// run as `cardemo replay FILE` without a trace, goal or output, so that chromium is timed on the
// very work that native and node are.

#include <emscripten/emscripten.h>

#include <string>
#include <utility>

#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "sim/world.hpp"

extern "C" {

/// Runs the replay at `path` (a file in the page's file system) to its end, headless, and returns
/// `frame N hash H`, or the `FILE:LINE: what is wrong` of a bad file.
EMSCRIPTEN_KEEPALIVE const char* cardemo_run_replay(const char* path) {
  static std::string result;
  const cardemo::Parsed<cardemo::Replay> replay = cardemo::loadReplay(path);
  cardemo::Parsed<cardemo::Scene> scene = replay.ok()
                                              ? cardemo::loadReplayScene(replay.value(), path, "")
                                              : cardemo::Parsed<cardemo::Scene>(replay.error());
  if (!scene.ok()) {
    result = scene.error().toString();
    return result.c_str();
  }
  cardemo::World world(std::move(scene).value(), cardemo::settingsForReplay(replay.value()));
  cardemo::runReplayInputs(world, replay.value());
  result =
      "frame " + std::to_string(world.frame()) + " hash " + cardemo::hashHex(world.stateHash());
  return result.c_str();
}

}  // extern "C"
