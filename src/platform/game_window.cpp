#include "platform/game_window.hpp"

#include <SDL.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "io/atomic_file.hpp"
#include "io/summary_json.hpp"
#include "platform/png_save.hpp"
#include "platform/sdl_canvas.hpp"
#include "platform/sprite_path.hpp"
#include "play/fixed_step_clock.hpp"
#include "play/input_latch.hpp"
#include "play/level_run.hpp"
#include "render/camera_rig.hpp"
#include "render/draw_world.hpp"
#include "render/effects.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void onStopSignal(int sig) {
  g_stop_signal = sig;
}

// SIGINT, SIGTERM and SIGHUP (terminal closed) only set a flag; the loop then exits normally,
// finishes the recording and writes the summary. SA_RESETHAND: a second signal of the same kind
// kills at once, which loses at most the last second of the recording (it is flushed every
// second). A full disk or a file-size limit must be an error on write, not SIGXFSZ; a closed
// standard output (--progress into a pipe) must not kill the game with SIGPIPE.
void installSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
}

// One line per simulated frame on standard output (--progress), written at once.
void printFrame(std::int64_t frame) {
  char line[32];
  const int n = std::snprintf(line, sizeof line, "%lld\n", static_cast<long long>(frame));
  if (n > 0) (void)::write(STDOUT_FILENO, line, static_cast<std::size_t>(n));
}

constexpr int kMaxStepsPerFrame = 8;
// The +/- keys scale the camera rig's zoom by zoom / kDefaultZoom.
constexpr double kDefaultZoom = 12.0, kMinZoom = 2.0, kMaxZoom = 80.0;
constexpr double kMinSpeed = 0.25, kMaxSpeed = 8.0;

struct SdlDeleter {
  void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
  void operator()(SDL_Renderer* r) const { SDL_DestroyRenderer(r); }
};

bool driveKey(SDL_Keycode code, DriveKey& key) {
  switch (code) {
    case SDLK_UP:
      key = DriveKey::kUp;
      return true;
    case SDLK_DOWN:
      key = DriveKey::kDown;
      return true;
    case SDLK_LEFT:
      key = DriveKey::kLeft;
      return true;
    case SDLK_RIGHT:
      key = DriveKey::kRight;
      return true;
    default:
      return false;
  }
}

// F12: the frame just drawn, saved as the first free `cardemo-shot-NNN.png` in the working folder.
std::string saveScreenshot(SDL_Renderer* renderer) {
  for (int n = 1; n < 1000; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "cardemo-shot-%03d.png", n);
    if (std::filesystem::exists(name)) continue;
    const std::string why = saveRendererPng(renderer, name);
    return why.empty() ? std::string("saved ") + name : why;
  }
  return "too many screenshots in this folder";
}

// Mutable state of the running window (everything but the session).
struct LoopState {
  bool quit = false;
  bool paused = false;
  bool step_once = false;
  bool restart = false;
  bool screenshot = false;
  double zoom = kDefaultZoom;
  double speed = 1.0;
  DrawOptions draw;
};

void handleKeyDown(const SDL_KeyboardEvent& key, LoopState& s, InputLatch& latch) {
  DriveKey drive{};
  if (driveKey(key.keysym.sym, drive)) {
    latch.press(drive);
    return;
  }
  if (key.repeat != 0) return;  // toggles act once per press
  switch (key.keysym.sym) {
    case SDLK_ESCAPE:
      s.quit = true;
      break;
    case SDLK_p:
      s.paused = !s.paused;
      break;
    case SDLK_n:
      if (s.paused) s.step_once = true;
      break;
    case SDLK_r:
      s.restart = true;
      break;
    case SDLK_b:
      s.draw.debug_overlay = !s.draw.debug_overlay;
      break;
    case SDLK_F1:
      s.draw.help = !s.draw.help;
      break;
    case SDLK_F12:
      s.screenshot = true;
      break;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
      s.zoom = std::min(kMaxZoom, s.zoom * 1.25);
      break;
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
      s.zoom = std::max(kMinZoom, s.zoom / 1.25);
      break;
    case SDLK_LEFTBRACKET:
      s.speed = std::max(kMinSpeed, s.speed * 0.5);
      break;
    case SDLK_RIGHTBRACKET:
      s.speed = std::min(kMaxSpeed, s.speed * 2.0);
      break;
    default:
      break;
  }
}

void pollEvents(LoopState& s, InputLatch& latch) {
  SDL_Event e;
  while (SDL_PollEvent(&e) != 0) {
    if (e.type == SDL_QUIT) {
      s.quit = true;
    } else if (e.type == SDL_KEYDOWN) {
      handleKeyDown(e.key, s, latch);
    } else if (e.type == SDL_KEYUP) {
      DriveKey drive{};
      if (driveKey(e.key.keysym.sym, drive)) latch.release(drive);
    } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
      // Key-up events go to the new focus; without this a key would stay held forever.
      latch.releaseAll();
    }
  }
}

int writeSummary(const std::string& path, const World& world, const LevelRun& level) {
  if (path.empty()) return 0;
  if (std::string why =
          writeFileAtomically(path, summaryJson(world, level.challenge()).dump(2) + "\n");
      !why.empty()) {
    std::fprintf(stderr, "%s\n", why.c_str());
    return 2;
  }
  return 0;
}

std::string statusLine(const GameSession& session, const GameWindowOptions& options,
                       const std::string& note) {
  std::string status = note;
  if (session.playingBack()) {
    status += (status.empty() ? "" : "  ") + std::string("replaying ") + options.replay_path +
              " (" + std::to_string(session.playbackLeft()) + " frames left)";
  }
  if (session.recording()) {
    status +=
        (status.empty() ? "" : "  ") + std::string("recording to ") + options.session.record_path;
  }
  return status;
}

int runLoop(SDL_Renderer* renderer, const GameWindowOptions& options) {
  const std::string json_path = options.json_path;
  GameSession session(options.session);
  if (!session.recordError().empty()) {
    std::fprintf(stderr, "%s\n", session.recordError().c_str());
    return 2;
  }
  SdlCanvas canvas(renderer);
  std::string sprite_error;
  if (const auto dir = findSpriteDir(&sprite_error)) sprite_error = canvas.loadImages(*dir);
  if (!sprite_error.empty())
    std::fprintf(stderr, "%s; drawing with vectors\n", sprite_error.c_str());
  int vw = 0, vh = 0;
  SDL_GetRendererOutputSize(renderer, &vw, &vh);
  Effects effects(session.world());
  CameraRig rig(session.world(), {vw, vh});
  const double hz = options.session.settings.hz;
  FixedStepClock clock(1.0 / hz, kMaxStepsPerFrame);
  InputLatch latch;
  LevelRun level(session.world(), bestScoresPath());
  LoopState s;
  std::string note;
  bool over_reported = false;
  bool record_error_reported = false;
  int status = 0;
  Uint64 last = SDL_GetPerformanceCounter();
  const double ticks_per_second = static_cast<double>(SDL_GetPerformanceFrequency());
  double fps = 0.0;

  while (!s.quit && g_stop_signal == 0) {
    pollEvents(s, latch);
    if (s.quit) break;
    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = static_cast<double>(now - last) / ticks_per_second;
    last = now;
    if (elapsed > 0.0) fps = fps == 0.0 ? 1.0 / elapsed : 0.95 * fps + 0.05 / elapsed;

    if (s.restart) {
      s.restart = false;
      session.restart();
      effects.reset(session.world());
      rig.reset(session.world());
      level.restart(session.world());
      latch.releaseAll();
      over_reported = false;
      note = "restarted";
    }
    int steps = s.paused ? 0 : clock.advance(elapsed, s.speed);
    if (s.paused && s.step_once) steps = 1;
    s.step_once = false;
    for (int i = 0; i < steps && !level.over(); ++i) {
      session.step(latch.sample());
      effects.observe(session.world());
      rig.step(session.world());
      if (level.observe(session.world()) && level.over()) {
        status = std::max(status, writeSummary(json_path, session.world(), level));
      }
      if (options.progress) printFrame(session.world().frame());
    }
    if (const std::string warning = level.takeWarning(); !warning.empty()) {
      std::fprintf(stderr, "%s\n", warning.c_str());
    }
    if (!record_error_reported && !session.recordError().empty()) {
      // Say so at once (disk full, file too large): the game goes on, the recording does not.
      record_error_reported = true;
      std::fprintf(stderr, "%s\n", session.recordError().c_str());
      note = "recording failed: see the terminal";
      status = 2;
    }
    if (session.world().gameOver() && !over_reported) {
      over_reported = true;
      status = std::max(status, writeSummary(json_path, session.world(), level));
      if (!record_error_reported && !session.recordError().empty()) {
        record_error_reported = true;
        std::fprintf(stderr, "%s\n", session.recordError().c_str());
        status = 2;
      }
    }

    const bool frozen = s.paused || session.world().gameOver() || level.over();
    const Obb2 box = session.blendedBox(frozen ? 1.0 : clock.alpha());
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer, &w, &h);
    s.draw.paused = s.paused;
    s.draw.fps = fps;
    s.draw.playback_speed = session.playingBack() || s.speed != 1.0 ? s.speed : 0.0;
    s.draw.status = statusLine(session, options, note);
    s.draw.effects = &effects;
    s.draw.sprites = true;
    const Camera camera =
        rig.camera({w, h}, frozen ? 1.0 : clock.alpha(), s.zoom / kDefaultZoom, effects.shake());
    GoalView goal_view;
    if (level.challenge() != nullptr) {
      goal_view = {level.challenge(), level.best(), level.newBest()};
      s.draw.game_over_rows = runSummaryRows(session.world(), goal_view);
    }
    drawFrame(canvas, session.world(), camera, box, s.draw);
    if (level.challenge() != nullptr) {
      drawGoalOverlay(canvas, session.world(), camera, box, goal_view);
    }
    if (s.screenshot) {
      s.screenshot = false;
      note = saveScreenshot(renderer);
    }
    SDL_RenderPresent(renderer);
    // Without vsync (e.g. under Xvfb) do not spin a core: about 250 frames per second is plenty.
    const double spent = static_cast<double>(SDL_GetPerformanceCounter() - now) / ticks_per_second;
    if (spent < 0.004) SDL_Delay(static_cast<Uint32>((0.004 - spent) * 1000.0) + 1);
  }

  if (std::string why = session.finishRecording(); !why.empty()) {
    if (!record_error_reported) std::fprintf(stderr, "%s\n", why.c_str());
    status = 2;
  }
  return std::max(status, writeSummary(json_path, session.world(), level));
}

}  // namespace

bool displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  // An explicit SDL video driver (offscreen, dummy, kmsdrm) needs no display server.
  const char* driver = std::getenv("SDL_VIDEODRIVER");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0') ||
         (driver != nullptr && *driver != '\0');
}

int runGameWindow(const GameWindowOptions& options) {
  // Our own handlers finish the recording; SDL's would only post SDL_QUIT.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr,
                 "cardemo play: cannot open a display (%s); use `cardemo render` for pictures or "
                 "`cardemo replay` for headless runs.\n",
                 SDL_GetError());
    return 1;
  }
  installSignalHandlers();
  const std::string title = "cardemo \xE2\x80\x94 " + options.session.scene.name;
  std::unique_ptr<SDL_Window, SdlDeleter> window(
      SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, 1280, 720,
                       SDL_WINDOW_RESIZABLE));
  if (!window) {
    std::fprintf(stderr,
                 "cardemo play: cannot open a window (%s); use `cardemo render` or "
                 "`cardemo replay` instead.\n",
                 SDL_GetError());
    SDL_Quit();
    return 1;
  }
  std::unique_ptr<SDL_Renderer, SdlDeleter> renderer(
      SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_PRESENTVSYNC));
  if (!renderer) renderer.reset(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_SOFTWARE));
  if (!renderer) {
    std::fprintf(stderr, "cardemo play: cannot create a renderer: %s\n", SDL_GetError());
    window.reset();
    SDL_Quit();
    return 1;
  }
  int status = runLoop(renderer.get(), options);
  renderer.reset();
  window.reset();
  SDL_Quit();
  if (g_stop_signal != 0)
    std::fprintf(stderr, "cardemo play: stopped by signal %d\n", g_stop_signal);
  return status;
}

}  // namespace cardemo
