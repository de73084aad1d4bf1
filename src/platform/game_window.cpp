#include "platform/game_window.hpp"

#include <SDL.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "io/atomic_file.hpp"
#include "io/summary_json.hpp"
#include "platform/game_audio.hpp"
#include "platform/game_controller.hpp"
#include "platform/png_save.hpp"
#include "platform/sdl_canvas.hpp"
#include "platform/sdl_window.hpp"
#include "platform/stop_signal.hpp"
#include "play/analog_drive.hpp"
#include "play/fixed_step_clock.hpp"
#include "play/input_latch.hpp"
#include "play/level_run.hpp"
#include "play/play_flow.hpp"
#include "play/sound_mix.hpp"
#include "render/camera_rig.hpp"
#include "render/draw_world.hpp"
#include "render/effects.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo {
namespace {

// One line per simulated frame on standard output (--progress), written at once.
void printFrame(std::int64_t frame) {
  char line[32];
  const int n = std::snprintf(line, sizeof line, "%lld\n", static_cast<long long>(frame));
  if (n > 0) (void)::write(STDOUT_FILENO, line, static_cast<std::size_t>(n));
}

constexpr int kMaxStepsPerFrame = 8;
// The +/- keys scale the camera rig's zoom by zoom / kDefaultZoom.
constexpr double kDefaultZoom = 12.0, kMinZoom = 2.0, kMaxZoom = 80.0;

// Arrows, and WASD by position (scancode), so the same physical keys drive on any layout; Space
// is the handbrake.
bool driveKey(const SDL_Keysym& key, DriveKey& out) {
  switch (key.scancode) {
    case SDL_SCANCODE_UP:
    case SDL_SCANCODE_W:
      out = DriveKey::kUp;
      return true;
    case SDL_SCANCODE_DOWN:
    case SDL_SCANCODE_S:
      out = DriveKey::kDown;
      return true;
    case SDL_SCANCODE_LEFT:
    case SDL_SCANCODE_A:
      out = DriveKey::kLeft;
      return true;
    case SDL_SCANCODE_RIGHT:
    case SDL_SCANCODE_D:
      out = DriveKey::kRight;
      return true;
    case SDL_SCANCODE_SPACE:
      out = DriveKey::kHandbrake;
      return true;
    default:
      return false;
  }
}

bool padDriveButton(Uint8 button, DriveKey& out) {
  switch (button) {
    case SDL_CONTROLLER_BUTTON_DPAD_UP:
      out = DriveKey::kUp;
      return true;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
      out = DriveKey::kDown;
      return true;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
      out = DriveKey::kLeft;
      return true;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
      out = DriveKey::kRight;
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

// No sound device is said once per process, not again for each scene the picker opens.
bool audio_reported = false;

// Mutable state of the running window (everything but the session and the flow).
struct LoopState {
  bool quit = false;    // window closed: end the program
  bool escape = false;  // Esc: back to the picker, or quit
  bool next = false;    // N: the next level once parked, else one step while paused
  bool restart = false;
  bool confirm = false;  // Enter, Space or the pad's A: restart once the game has ended
  bool screenshot = false;
  bool fullscreen = false;
  bool toggle_mute = false;
  double zoom = kDefaultZoom;
  DrawOptions draw;
};

// Everything that reads input events, in one place.
struct Inputs {
  InputLatch latch;
  AnalogDrive analog;
  GameController pad;
};

void toggleFullscreen(SDL_Window* window, LoopState& s) {
  s.fullscreen = !s.fullscreen;
  // Desktop full screen: the desktop's resolution, no mode switch.
  if (SDL_SetWindowFullscreen(window, s.fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0) != 0) {
    s.fullscreen = !s.fullscreen;
  }
}

void handleKeyDown(const SDL_KeyboardEvent& key, LoopState& s, PlayFlow& flow, Inputs& in,
                   SDL_Window* window) {
  DriveKey drive{};
  if (driveKey(key.keysym, drive)) {
    in.latch.press(drive);
    flow.driveKeyPressed();
    // Space is also "restart" once the game has ended (the flow decides).
    if (drive == DriveKey::kHandbrake && key.repeat == 0) s.confirm = true;
    return;
  }
  if (key.repeat != 0) return;  // toggles act once per press
  switch (key.keysym.sym) {
    case SDLK_ESCAPE:
      s.escape = true;
      break;
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
      s.confirm = true;
      break;
    case SDLK_p:
      flow.togglePause();
      break;
    case SDLK_n:
      s.next = true;
      break;
    case SDLK_r:
      s.restart = true;
      break;
    case SDLK_b:
      s.draw.debug_overlay = !s.draw.debug_overlay;
      break;
    case SDLK_m:
      s.toggle_mute = true;
      break;
    case SDLK_F1:
      flow.toggleHelp();
      break;
    case SDLK_F11:
      toggleFullscreen(window, s);
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
      flow.slower();
      break;
    case SDLK_RIGHTBRACKET:
      flow.faster();
      break;
    default:
      break;
  }
}

void handlePadButton(const SDL_ControllerButtonEvent& button, bool down, LoopState& s,
                     PlayFlow& flow, Inputs& in) {
  if (!in.pad.owns(button.which)) return;
  DriveKey drive{};
  if (padDriveButton(button.button, drive)) {
    if (down) {
      in.latch.press(drive);
      flow.driveKeyPressed();
    } else {
      in.latch.release(drive);
    }
    return;
  }
  if (!down) return;
  if (button.button == SDL_CONTROLLER_BUTTON_START) flow.togglePause();
  if (button.button == SDL_CONTROLLER_BUTTON_A) s.confirm = true;
  if (button.button == SDL_CONTROLLER_BUTTON_BACK) s.restart = true;
}

void pollEvents(LoopState& s, PlayFlow& flow, Inputs& in, SDL_Window* window) {
  SDL_Event e;
  while (SDL_PollEvent(&e) != 0) {
    if (in.pad.handleDeviceEvent(e)) continue;
    if (e.type == SDL_QUIT) {
      s.quit = true;
    } else if (e.type == SDL_KEYDOWN) {
      handleKeyDown(e.key, s, flow, in, window);
    } else if (e.type == SDL_KEYUP) {
      DriveKey drive{};
      if (driveKey(e.key.keysym, drive)) in.latch.release(drive);
    } else if (e.type == SDL_CONTROLLERBUTTONDOWN || e.type == SDL_CONTROLLERBUTTONUP) {
      handlePadButton(e.cbutton, e.type == SDL_CONTROLLERBUTTONDOWN, s, flow, in);
    } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
      // Key-up events go to the new focus; without this a key would stay held forever.
      in.latch.releaseAll();
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

// Once the run has ended nothing is replayed or recorded any more: the line says where the
// recording was saved instead.
std::string statusLine(const GameSession& session, const GameWindowOptions& options,
                       const std::string& note, bool ended) {
  std::string status = note;
  if (ended && !session.recordPath().empty() && session.recordError().empty()) {
    status += (status.empty() ? "" : "  ") + std::string("recorded to ") + session.recordPath();
  }
  if (ended) return status;
  if (session.playingBack()) {
    status += (status.empty() ? "" : "  ") + std::string("replaying ") + options.replay_path +
              " (" + std::to_string(session.playbackLeft()) + " frames left)";
  }
  if (session.recording()) {
    status += (status.empty() ? "" : "  ") + std::string("recording to ") + session.recordPath();
  }
  return status;
}

// Reports a recording error once per attempt; returns 2 when there was one.
int reportRecordError(const GameSession& session, bool& reported, std::string& note) {
  if (reported || session.recordError().empty()) return 0;
  reported = true;
  std::fprintf(stderr, "%s\n", session.recordError().c_str());
  note = "recording failed: see the terminal";
  return 2;
}

}  // namespace

GameOutcome runGame(SdlWindow& sdl, const GameWindowOptions& options) {
  SDL_Window* window = sdl.window();
  SDL_Renderer* renderer = sdl.renderer();
  installStopSignals();
  sdl.setTitle(windowTitle(options.session.scene.name));
  GameOutcome outcome;
  const std::string json_path = options.json_path;
  GameSession session(options.session);
  outcome.last_attempt = session.attempt();
  if (!session.recordError().empty()) {
    std::fprintf(stderr, "%s\n", session.recordError().c_str());
    outcome.status = 2;
    return outcome;
  }
  SdlCanvas canvas(renderer);
  const std::string sprite_error = canvas.loadSprites();
  if (!sprite_error.empty())
    std::fprintf(stderr, "%s; drawing with vectors\n", sprite_error.c_str());
  int vw = 0, vh = 0;
  SDL_GetRendererOutputSize(renderer, &vw, &vh);
  Effects effects(session.world());
  CameraRig rig(session.world(), {vw, vh});
  const double hz = options.session.settings.hz;
  FixedStepClock clock(1.0 / hz, kMaxStepsPerFrame);
  Inputs in;
  PlayFlow flow;
  // A replay being watched shows the best score but never sets one: the player did not drive it.
  LevelRun level(session.world(), bestScoresPath(), options.session.playback.empty());
  GameAudio audio(options.sounds_dir, options.mute);
  SoundMix sound;
  InputFrame last_input;
  // No sound is not an error: say so once, unless the player asked for silence (then on M).
  if (!options.mute && !audio.message().empty() && !audio_reported) {
    audio_reported = true;
    std::fprintf(stderr, "cardemo play: %s\n", audio.message().c_str());
  }
  LoopState s;
  s.fullscreen = (SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
  std::string note;
  bool over_reported = false;
  bool record_error_reported = false;
  int status = 0;
  Uint64 last = SDL_GetPerformanceCounter();
  const double ticks_per_second = static_cast<double>(SDL_GetPerformanceFrequency());
  double fps = 0.0;
  std::int64_t drawn_frames = 0;

  while (!s.quit && stopSignal() == 0) {
    pollEvents(s, flow, in, window);
    if (s.quit) break;
    if (s.escape) {
      outcome.exit = escapeExit(options.links);
      break;
    }
    if (s.next) {
      s.next = false;
      const bool parked = level.challenge() != nullptr && level.challenge()->parkedFrame();
      if (flow.next(parked, options.links) == LevelExit::kNextLevel) {
        outcome.exit = LevelExit::kNextLevel;
        break;
      }
    }
    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = static_cast<double>(now - last) / ticks_per_second;
    last = now;
    // The first pass measures no drawn frame (a few microseconds after start-up): skip it, or a
    // game opened from the picker starts with an FPS in the tens of thousands.
    if (elapsed > 0.0 && drawn_frames++ > 0) {
      fps = fps == 0.0 ? 1.0 / elapsed : 0.95 * fps + 0.05 / elapsed;
    }

    // GAME OVER, or a level's PARKED / TIME UP: Enter or Space starts the next attempt.
    const auto ended = [&] { return session.ended() || level.over(); };
    if (s.confirm && flow.confirm(ended())) s.restart = true;
    s.confirm = false;
    if (s.restart) {
      s.restart = false;
      // The attempt that ends here is published under its own name before the next one starts.
      if (const std::string why = session.finishRecording();
          !why.empty() && !record_error_reported) {
        std::fprintf(stderr, "%s\n", why.c_str());
        status = 2;
      }
      session.restart();
      effects.reset(session.world());
      rig.reset(session.world());
      level.restart(session.world());
      in.latch.releaseAll();
      in.analog.reset();
      flow.restarted();
      over_reported = false;
      record_error_reported = false;
      note = "attempt " + std::to_string(session.sceneAttempt());
      status = std::max(status, reportRecordError(session, record_error_reported, note));
    }
    if (s.toggle_mute) {
      s.toggle_mute = false;
      audio.toggleMute();
      if (!audio.available() && !audio_reported) {
        audio_reported = true;
        std::fprintf(stderr, "cardemo play: %s\n", audio.message().c_str());
      }
      note = !audio.available() ? "no sound: see the terminal"
             : audio.muted()    ? "sound off"
                                : "sound on";
    }
    const PadState pad = in.pad.read();
    if (pad.throttle > 0.0 || pad.brake > 0.0 || pad.steer != 0.0 || pad.handbrake) {
      flow.driveKeyPressed();
    }
    flow.update(session.playingBack(), ended());
    const int steps = flow.stepsToRun(flow.holding() ? 0 : clock.advance(elapsed, flow.speed()));
    for (int i = 0; i < steps && !ended(); ++i) {
      last_input = session.step(mergeInputs(in.latch.sample(), in.analog.sample(pad)));
      effects.observe(session.world());
      rig.step(session.world());
      if (level.observe(session.world()) && level.over()) {
        status = std::max(status, writeSummary(json_path, session.world(), level));
        if (level.challenge()->parkedFrame()) audio.playChime();
        // Nothing more is simulated: publish this attempt's recording now, as GAME OVER does.
        (void)session.finishRecording();
      }
      if (options.progress) printFrame(session.world().frame());
      // A replay that runs out mid-frame hands over at once, not after the frame's other steps.
      flow.update(session.playingBack(), ended());
      if (flow.holding()) break;
    }
    if (ended()) effects.idle(steps);
    if (const std::string warning = level.takeWarning(); !warning.empty()) {
      std::fprintf(stderr, "%s\n", warning.c_str());
    }
    status = std::max(status, reportRecordError(session, record_error_reported, note));
    if (session.world().gameOver() && !over_reported) {
      over_reported = true;
      status = std::max(status, writeSummary(json_path, session.world(), level));
      status = std::max(status, reportRecordError(session, record_error_reported, note));
    }

    // Once the run is over the engine idles: no throttle from a key still held at the end.
    audio.apply(sound.update(session.world(), ended() ? InputFrame{} : last_input, flow.holding()));

    const bool frozen = flow.holding() || session.world().gameOver() || level.over();
    const Obb2 box = session.blendedBox(frozen ? 1.0 : clock.alpha());
    int w = 0, h = 0;
    SDL_GetRendererOutputSize(renderer, &w, &h);
    // After the end nothing runs anyway: the end panel, not PAUSED, says what is going on.
    s.draw.paused = (flow.paused() && !ended()) || flow.help();
    s.draw.help = flow.help();
    s.draw.banner = flow.yourTurn() ? "YOUR TURN: drive to take over" : "";
    s.draw.fps = fps;
    s.draw.playback_speed = session.playingBack() && !ended() ? flow.chosenSpeed() : 0.0;
    s.draw.status = statusLine(session, options, note, ended());
    s.draw.run_over = ended();
    s.draw.game_over_keys = endPanelKeys(options.links, false);
    s.draw.effects = &effects;
    s.draw.sprites = true;
    const Camera camera =
        rig.camera({w, h}, frozen ? 1.0 : clock.alpha(), s.zoom / kDefaultZoom, effects.shake());
    GoalView goal_view;
    s.draw.goal = nullptr;
    if (level.challenge() != nullptr) {
      goal_view = {level.challenge(), level.best(), level.newBest(),
                   endPanelKeys(options.links, level.challenge()->parkedFrame().has_value())};
      s.draw.game_over_rows = runSummaryRows(session.world(), goal_view);
      s.draw.goal = &goal_view;
    }
    drawFrame(canvas, session.world(), camera, box, s.draw);
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
  outcome.last_attempt = session.attempt();
  outcome.status = std::max(status, writeSummary(json_path, session.world(), level));
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
      SdlWindow::open(windowTitle(options.session.scene.name), error);
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
