// `cardemo play`: finds the scene, loads the replay, then hands over to the window (src/platform).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "app/commands.hpp"
#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "platform/asset_folders.hpp"
#include "platform/game_window.hpp"
#include "play/recorder.hpp"

namespace cardemo::app {
namespace {

namespace fs = std::filesystem;

struct PlayOptions {
  std::string scene_path;
  std::string record_path;
  std::string replay_path;
  std::string json_path;
  int hz = 120;
  bool progress = false;
};

constexpr const char* kDefaultScene = "scenes/parking-lot.json";

// The bundled lot: $CARDEMO_ASSETS first, then next to the executable (installed or build tree).
std::string findDefaultScene() {
  for (const fs::path& folder : assetFolders()) {
    std::error_code ec;
    const fs::path candidate = folder / kDefaultScene;
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
  }
  return {};
}

int runPlayCommand(const PlayOptions& options) {
  if (!displayAvailable()) {
    std::fprintf(stderr,
                 "cardemo play: no display (DISPLAY and WAYLAND_DISPLAY are unset); use `cardemo "
                 "render` for pictures or `cardemo replay` for headless runs.\n");
    return 1;
  }
  if (options.hz < 1 || options.hz > 10000) {
    std::fprintf(stderr, "cardemo play: --hz must be 1..10000\n");
    return 2;
  }
  if (!options.record_path.empty()) {
    // Before any window: a recording left by a killed game is kept and pointed at, not replaced.
    if (const std::string why = leftoverRecording(options.record_path); !why.empty()) {
      std::fprintf(stderr, "%s\n", why.c_str());
      return 2;
    }
  }
  GameWindowOptions window;
  window.json_path = options.json_path;
  window.progress = options.progress;
  window.replay_path = options.replay_path;
  SessionConfig& session = window.session;
  session.settings.hz = options.hz;
  session.record_path = options.record_path;

  std::string scene_path = options.scene_path;
  std::optional<Parsed<Scene>> replay_scene;  // the replay's own scene, when SCENE is not given
  if (!options.replay_path.empty()) {
    Parsed<Replay> replay = loadReplay(options.replay_path);
    if (!replay.ok()) {
      std::fprintf(stderr, "%s\n", replay.error().toString().c_str());
      return 2;
    }
    if (scene_path.empty()) {
      if (replay.value().scene.empty()) {
        std::fprintf(stderr, "%s:1: the replay names no scene; give SCENE\n",
                     options.replay_path.c_str());
        return 2;
      }
      scene_path = replay.value().scene_resolved;
      replay_scene = loadSceneOfReplay(replay.value(), options.replay_path);
    }
    session.settings = settingsForReplay(replay.value());
    session.playback = std::move(replay).value().runs;
  }
  if (scene_path.empty()) {
    scene_path = findDefaultScene();
    if (scene_path.empty()) {
      std::fprintf(stderr,
                   "cardemo play: cannot find the bundled %s next to the executable; give SCENE "
                   "or set CARDEMO_ASSETS to the assets folder\n",
                   kDefaultScene);
      return 2;
    }
  }
  Parsed<Scene> scene = replay_scene ? std::move(*replay_scene) : loadScene(scene_path);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.error().toString().c_str());
    return 2;
  }
  session.scene = std::move(scene).value();
  session.scene_path = scene_path;
  return runGameWindow(window);
}

}  // namespace

void addPlayCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<PlayOptions>();
  CLI::App* sub = app.add_subcommand("play", "Drive in a window with the arrow keys (F1: help)");
  sub->add_option("SCENE", options->scene_path,
                  "Scene file (default: the bundled parking lot, or the replay's scene)");
  sub->add_option("--record", options->record_path,
                  "Record every simulated step to FILE as a replay (FILE.part while playing)");
  sub->add_option("--replay", options->replay_path,
                  "Play a replay's inputs first; the keyboard takes over when it ends");
  sub->add_option("--json", options->json_path,
                  "Write the summary JSON to FILE when the game ends");
  sub->add_flag("--progress", options->progress,
                "Print each simulated frame's number on standard output as it is stepped (for "
                "scripts and tests)");
  sub->add_option("--hz", options->hz,
                  "Fixed simulation rate in steps per second (default 120; a replay uses its own)");
  sub->callback([options, &exit_code] { exit_code = runPlayCommand(*options); });
}

}  // namespace cardemo::app
