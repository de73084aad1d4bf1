#include "platform/game_window.hpp"

#include <SDL.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "platform/game_audio.hpp"
#include "platform/game_controller.hpp"
#include "platform/png_save.hpp"
#include "platform/sdl_canvas.hpp"
#include "platform/sdl_keys.hpp"
#include "platform/sdl_window.hpp"
#include "platform/stop_signal.hpp"
#include "play/key_map.hpp"

namespace cardemo {
namespace {

// One line per simulated frame on standard output (--progress), written at once.
void printFrame(std::int64_t frame) {
  char line[32];
  const int n = std::snprintf(line, sizeof line, "%lld\n", static_cast<long long>(frame));
  if (n > 0) (void)::write(STDOUT_FILENO, line, static_cast<std::size_t>(n));
}

void printMessages(PlayScreen& screen) {
  for (const std::string& line : screen.takeMessages()) std::fprintf(stderr, "%s\n", line.c_str());
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

void toggleFullscreen(SDL_Window* window) {
  const bool full = (SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
  // Desktop full screen: the desktop's resolution, no mode switch.
  (void)SDL_SetWindowFullscreen(window, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
}

Eigen::Vector2i outputSize(SDL_Renderer* renderer) {
  int w = 0, h = 0;
  SDL_GetRendererOutputSize(renderer, &w, &h);
  return {w, h};
}

// The events waiting, as the frame's actions (play/key_map says what each key does).
void pollActions(GameController& pad, std::vector<PlayAction>& out) {
  SDL_Event e;
  while (SDL_PollEvent(&e) != 0) {
    if (pad.handleDeviceEvent(e)) continue;
    if (e.type == SDL_QUIT) {
      out.push_back({PlayActionKind::kQuit});
    } else if (e.type == SDL_KEYDOWN || e.type == SDL_KEYUP) {
      const std::optional<GameKey> key = gameKeyOf(e.key.keysym);
      if (!key) continue;
      if (e.type == SDL_KEYDOWN) {
        keyDownActions(*key, e.key.repeat != 0, out);
      } else {
        keyUpActions(*key, out);
      }
    } else if (e.type == SDL_CONTROLLERBUTTONDOWN || e.type == SDL_CONTROLLERBUTTONUP) {
      const std::optional<PadButton> button = padButtonOf(e.cbutton.button);
      if (button && pad.owns(e.cbutton.which)) {
        padButtonActions(*button, e.type == SDL_CONTROLLERBUTTONDOWN, out);
      }
    } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
      // Key-up events go to the new focus; without this a key would stay held forever.
      out.push_back({PlayActionKind::kReleaseAll});
    }
  }
}

// No sound device is said once per process, not again for each scene the picker opens.
bool sound_problem_reported = false;

}  // namespace

GameOutcome runGame(SdlWindow& sdl, const GameWindowOptions& options) {
  SDL_Window* window = sdl.window();
  SDL_Renderer* renderer = sdl.renderer();
  installStopSignals();
  sdl.setTitle(windowTitle(options.play.session.scene.name));
  GameAudio audio(options.sounds_dir, options.play.muted);
  PlayScreenConfig config = options.play;
  config.viewport = outputSize(renderer);
  config.sound = {audio.available(), audio.message(), sound_problem_reported};
  if (options.progress) config.on_step = printFrame;
  PlayScreen screen(std::move(config));
  if (!screen.ready()) {
    printMessages(screen);
    return screen.outcome();
  }
  SdlCanvas canvas(renderer);
  const std::string sprite_error = canvas.loadSprites();
  if (!sprite_error.empty())
    std::fprintf(stderr, "%s; drawing with vectors\n", sprite_error.c_str());
  GameController pad;
  std::vector<PlayAction> actions;
  Uint64 last = SDL_GetPerformanceCounter();
  const double ticks_per_second = static_cast<double>(SDL_GetPerformanceFrequency());

  while (stopSignal() == 0) {
    actions.clear();
    pollActions(pad, actions);
    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = static_cast<double>(now - last) / ticks_per_second;
    last = now;
    const PlayFrame& frame = screen.frame({actions, pad.read(), elapsed, outputSize(renderer)});
    printMessages(screen);
    if (frame.toggle_fullscreen) toggleFullscreen(window);
    if (frame.exit != LevelExit::kStay) break;
    if (audio.muted() != frame.muted) audio.toggleMute();
    if (frame.chime) audio.playChime();
    audio.apply(frame.sound);
    drawPlayFrame(canvas, frame);
    if (frame.screenshot) screen.showNote(saveScreenshot(renderer));
    SDL_RenderPresent(renderer);
    // Without vsync (e.g. under Xvfb) do not spin a core: about 250 frames per second is plenty.
    const double spent = static_cast<double>(SDL_GetPerformanceCounter() - now) / ticks_per_second;
    if (spent < 0.004) SDL_Delay(static_cast<Uint32>((0.004 - spent) * 1000.0) + 1);
  }
  const GameOutcome outcome = screen.finish();
  printMessages(screen);
  sound_problem_reported = screen.soundProblemReported();
  return outcome;
}

bool displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  // An explicit SDL video driver (offscreen, dummy, kmsdrm) needs no display server.
  const char* driver = std::getenv("SDL_VIDEODRIVER");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0') ||
         (driver != nullptr && *driver != '\0');
}

int runGameWindow(const GameWindowOptions& options) {
  std::string error;
  const std::unique_ptr<SdlWindow> window =
      SdlWindow::open(windowTitle(options.play.session.scene.name), error);
  if (!window) {
    std::fprintf(stderr,
                 "cardemo play: %s; use `cardemo render` for pictures or `cardemo replay` for "
                 "headless runs.\n",
                 error.c_str());
    return 1;
  }
  const int status = runGame(*window, options).status;
  if (stopSignal() != 0) std::fprintf(stderr, "cardemo play: stopped by signal %d\n", stopSignal());
  return status;
}

}  // namespace cardemo
