// `cardemo play`: finds the scene, loads the replay, then hands over to the window (src/platform).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "io/asset_lookup.hpp"
#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "platform/game_window.hpp"
#include "platform/scene_picker.hpp"
#include "play/best_scores.hpp"
#include "play/level_list.hpp"
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
  bool mute = false;
};

constexpr const char* kDefaultScene = "scenes/parking-lot.json";

// The folder of the bundled sounds (assets/sounds, io/asset_lookup); empty when absent.
std::string findSounds() {
  const std::optional<std::string> engine = findAsset("sounds/engine-1.wav");
  return engine ? fs::path(*engine).parent_path().string() : std::string();
}

// Without SCENE or --replay: the picker lists the levels and the free-drive lot, and opens them in
// one window (Esc in a level returns to it). `window` holds everything but the scene.
int pickAndPlay(const GameWindowOptions& window) {
  std::string why;
  const std::optional<std::string> lot = findAsset(kDefaultScene, &why);
  if (!lot) {
    std::fprintf(stderr, "cardemo play: %s, or give SCENE\n", why.c_str());
    return 2;
  }
  // The assets folder that holds scenes/parking-lot.json.
  const std::string assets = fs::path(*lot).parent_path().parent_path().string();
  std::vector<std::string> warnings;
  const std::vector<LevelEntry> entries = listLevels(assets, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
  return runPickerAndLevels(entries, window);
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
  window.play.json_path = options.json_path;
  window.play.replay_path = options.replay_path;
  window.play.best_scores_path = bestScoresPath();
  window.play.muted = options.mute;
  window.progress = options.progress;
  window.sounds_dir = findSounds();
  SessionConfig& session = window.play.session;
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
  if (scene_path.empty()) return pickAndPlay(window);
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
  CLI::App* sub =
      app.add_subcommand("play", "Drive in a window with the arrow keys or WASD (F1: help)");
  sub->add_option("SCENE", options->scene_path,
                  "Scene file (default: the replay's scene, else a picker of the bundled levels "
                  "and the free-drive lot)");
  sub->add_option(
      "--record", options->record_path,
      "Record every simulated step to FILE as a replay (FILE.part while playing); after a "
      "restart, attempt N records to FILE-N (drive.replay, drive-2.replay, ...)");
  sub->add_option(
      "--replay", options->replay_path,
      "Play a replay's inputs first; when it ends the game waits (YOUR TURN) until you drive");
  sub->add_option("--json", options->json_path,
                  "Write the summary JSON to FILE when the game ends");
  sub->add_flag("--progress", options->progress,
                "Print each simulated frame's number on standard output as it is stepped (for "
                "scripts and tests)");
  sub->add_flag("--mute", options->mute, "Start with the sound off (M toggles it)");
  sub->add_option("--hz", options->hz,
                  "Fixed simulation rate in steps per second (default 120; a replay uses its own)");
  sub->callback([options, &exit_code] { exit_code = runPlayCommand(*options); });
}

}  // namespace cardemo::app
