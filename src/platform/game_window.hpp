#pragma once
/// The game window (`cardemo play`). This header is SDL-free so the command can stay SDL-free.

#include <string>

#include "play/game_session.hpp"
#include "play/play_flow.hpp"

namespace cardemo {

class SdlWindow;

/// What the window plays.
struct GameWindowOptions {
  SessionConfig session;    ///< Scene, rate, playback and recording.
  std::string json_path;    ///< Summary JSON written when the game ends (empty: none).
  std::string replay_path;  ///< The replay being played, for the status line (may be empty).
  bool progress = false;    ///< Print each simulated frame's number on standard output.
  std::string sounds_dir;   ///< Folder of the WAVs (assets/sounds); empty: not found, silent.
  bool mute = false;        ///< Start with the sound off (M toggles).
  LevelLinks links;         ///< Started from the picker, and whether a next level follows.
};

/// How one game in the window ended.
struct GameOutcome {
  int status = 0;                     ///< 0, or 2 when an output could not be written.
  LevelExit exit = LevelExit::kQuit;  ///< What the player asked for (kQuit also on a signal).
  int last_attempt = 1;               ///< Number of the last attempt played (recording paths).
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
