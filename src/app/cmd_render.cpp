// `cardemo render`: one frame of a scene or a replay, drawn without a window or display into a PNG.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "platform/png_render.hpp"
#include "render/camera_rig.hpp"
#include "render/effects.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo::app {
namespace {

struct RenderOptions {
  std::string input;
  std::string scene_path;
  std::string out;
  std::optional<std::int64_t> frame;
  bool debug = false;
  bool help = false;
  bool paused = false;
  bool sprites = false;
  bool rig = false;
  bool bay_chain = false;
  bool zoom_given = false;
  int width = 1280;
  int height = 720;
  double zoom = 12.0;
  std::vector<double> center;
};

bool isReplayFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  if (!in || !std::getline(in, first)) return false;
  if (!first.empty() && first.back() == '\r') first.pop_back();
  return first == "cardemo-replay 1";
}

int fail(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  return 2;
}

// What watches the world step by step, as the window's do: hit feedback, the camera rig, the
// level's challenge and free drive's bay chain (their timer, readout and end panel are drawn).
struct Observers {
  Effects effects;
  CameraRig rig;
  std::optional<ParkingChallenge> challenge;
  std::optional<BayChain> chain;
  void step(World& world, const InputFrame& input) {
    world.step(input);
    effects.observe(world);
    rig.step(world);
    if (challenge) challenge->observe(world);
    if (chain) chain->observe(world);
  }
};

// Steps the world through the replay's inputs up to `frame`.
void runReplayTo(World& world, Observers& observers, const Replay& replay, std::int64_t frame) {
  for (const InputRun& run : replay.runs) {
    for (std::int64_t i = 0; i < run.count; ++i) {
      if (world.frame() >= frame) return;
      observers.step(world, run.keys);
    }
  }
}

std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

int runRenderCommand(const RenderOptions& options) {
  // CLI::Range lets NaN through (every comparison with it is false).
  if (!(options.zoom >= 0.01 && options.zoom <= 10000.0)) {
    return fail("cardemo render: --zoom must be a number from 0.01 to 10000 pixels per metre");
  }
  for (double c : options.center) {
    if (!(std::abs(c) <= 1e9)) return fail("cardemo render: --center must be two finite numbers");
  }
  std::optional<World> world;
  std::optional<Observers> observers;
  const Eigen::Vector2i viewport{options.width, options.height};
  auto watch = [&] {
    observers.emplace(
        Observers{Effects(*world), CameraRig(*world, viewport), startChallenge(*world), {}});
    // As the game: the chain only on a scene without a goal, and with a free bay.
    if (options.bay_chain && !observers->challenge) {
      BayChain chain = startBayChain(*world);
      if (!chain.bays().empty()) observers->chain.emplace(std::move(chain));
    }
  };
  if (isReplayFile(options.input)) {
    const Parsed<Replay> replay = loadReplay(options.input);
    if (!replay.ok()) return fail(replay.error().toString());
    Parsed<Scene> scene = loadReplayScene(replay.value(), options.input, options.scene_path);
    if (!scene.ok()) return fail(scene.error().toString());
    const std::int64_t total = replay.value().totalFrames();
    const std::int64_t frame = options.frame.value_or(total);
    if (frame > total) {
      return fail(options.input + ": --frame " + std::to_string(frame) +
                  " is beyond the end of the replay (frames 0 to " + std::to_string(total) + ")");
    }
    world.emplace(std::move(scene).value(), settingsForReplay(replay.value()));
    watch();
    runReplayTo(*world, *observers, replay.value(), frame);
  } else {
    if (!options.scene_path.empty()) {
      return fail(options.input + ": --scene applies to replays only (this is not a replay)");
    }
    Parsed<Scene> scene = loadScene(options.input);
    if (!scene.ok()) return fail(scene.error().toString());
    world.emplace(std::move(scene).value());
    watch();
    // A scene has no inputs: frame N is N steps with nothing held.
    for (std::int64_t i = 0; i < options.frame.value_or(0); ++i) {
      observers->step(*world, InputFrame{});
    }
  }

  RenderSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.pixels_per_metre = options.zoom;
  if (!options.center.empty())
    settings.center = Eigen::Vector2d(options.center[0], options.center[1]);
  if (options.rig) {
    if (options.zoom_given) observers->rig.setBaseZoom(options.zoom);
    settings.camera = observers->rig.camera(viewport, 1.0, 1.0, observers->effects.shake());
  }
  settings.options.effects = &observers->effects;
  settings.options.sprites = options.sprites;
  settings.options.debug_overlay = options.debug;
  settings.options.frame_counter = true;  // a picture of frame N says which frame it is
  settings.options.help = options.help;
  settings.options.paused = options.paused;
  GoalView goal;
  if (observers->challenge) {
    goal.challenge = &*observers->challenge;
    settings.options.goal = &goal;
  } else if (observers->chain) {
    goal.challenge = &observers->chain->challenge();
    goal.chain = &*observers->chain;
    settings.options.goal = &goal;
    settings.options.game_over_rows = chainSummaryRows(*world, goal);
  }
  settings.options.status = baseName(options.input) + "  -  " + world->scene().name;
  if (std::string why = renderPng(*world, settings, options.out); !why.empty()) return fail(why);
  std::printf("wrote %s (%dx%d, frame %lld)\n", options.out.c_str(), options.width, options.height,
              static_cast<long long>(world->frame()));
  return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* sub = app.add_subcommand(
      "render", "Draw one frame of a scene or replay into a PNG, with no window or display");
  sub->add_option("INPUT", options->input,
                  "Scene (JSON) or replay (a file starting `cardemo-replay 1`)")
      ->required();
  sub->add_option("--out", options->out, "PNG file to write")->required();
  sub->add_option("--frame", options->frame,
                  "Frame to draw (replay: default the last; scene: default 0, N = N steps with no "
                  "input)")
      ->check(CLI::Range(std::int64_t{0}, kMaxReplayFrames));
  sub->add_option("--scene", options->scene_path,
                  "Scene file for a replay; overrides the replay's `scene` line");
  sub->add_option("--center", options->center,
                  "World point X Y (metres) at the middle of the picture (default: the player)")
      ->expected(2);
  sub->add_flag("--debug", options->debug,
                "Draw the debug overlay (AABB, OBBs, candidates, contacts, counters)");
  sub->add_flag("--help-panel", options->help, "Draw the F1 help panel");
  sub->add_flag("--paused", options->paused, "Draw the PAUSED banner");
  sub->add_flag(
      "--sprites", options->sprites,
      "Draw cars, tyres and ground with the sprites in assets/sprites (default: vectors)");
  sub->add_flag("--bay-chain", options->bay_chain,
                "Free drive's bay chain on a scene without a goal: the highlighted bay, the next, "
                "the time left and the count, as the game draws them");
  sub->add_flag("--rig", options->rig,
                "Frame the picture as the game does: look-ahead, speed zoom, held inside the walls "
                "(zoom fitted to the scene unless --zoom is given)")
      ->excludes("--center");
  sub->add_option("--width", options->width, "Image width in pixels (16 to 8192)")
      ->check(CLI::Range(16, 8192));
  sub->add_option("--height", options->height, "Image height in pixels (16 to 8192)")
      ->check(CLI::Range(16, 8192));
  CLI::Option* zoom = sub->add_option("--zoom", options->zoom, "Pixels per metre (0.01 to 10000)")
                          ->check(CLI::Range(0.01, 10000.0));
  sub->parse_complete_callback([options, zoom] { options->zoom_given = zoom->count() > 0; });
  sub->callback([options, &exit_code] { exit_code = runRenderCommand(*options); });
}

}  // namespace cardemo::app
