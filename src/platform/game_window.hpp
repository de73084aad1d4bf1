#pragma once
/// The game window (`cardemo play`). This header is SDL-free so the command can stay SDL-free.

#include <string>

#include "play/play_screen.hpp"

namespace cardemo {

class SdlWindow;

/// What the window plays.
struct GameWindowOptions {
  PlayScreenConfig play;   ///< The level: scene, playback, recording, summary, links, mute.
  bool progress = false;   ///< Print each simulated frame's number on standard output.
  std::string sounds_dir;  ///< Folder of the WAVs (assets/sounds); empty: not found, silent.
};

/// True when an X11 or Wayland display is named in the environment, or SDL_VIDEODRIVER names a
/// driver (such as `offscreen`, which needs no display).
[[nodiscard]] bool displayAvailable();

/// Plays one scene in an open window until Esc, N on a parked level with a next one, window close,
/// SIGINT, SIGTERM or SIGHUP, then finishes the recording and writes the summary.
[[nodiscard]] GameOutcome runGame(SdlWindow& sdl, const GameWindowOptions& options);

/// Opens the window and runs the game (runGame) in it. Returns the exit status: 0 normally, 1 when
/// no display can be opened, 2 when an output cannot be written.
[[nodiscard]] int runGameWindow(const GameWindowOptions& options);

}  // namespace cardemo
