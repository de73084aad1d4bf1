#pragma once
/// The subcommands of the `cardemo` executable. Each registers itself on the CLI11 app and, when
/// chosen, stores its exit status (0 ok, 1 a check failed, 2 bad input) in `exit_code`.

#include <CLI/CLI.hpp>
#include <string>

namespace cardemo::app {

/// `cardemo replay REPLAY [--scene S] [--json FILE|-] [--trace FILE] [--print-expect]`.
void addReplayCommand(CLI::App& app, int& exit_code);

/// `cardemo collide PAIRS [--dim 2|3]`.
void addCollideCommand(CLI::App& app, int& exit_code);

/// `cardemo NAME ...` in a build without it: hidden from --help; says that it needs `needs` and
/// exits 2.
void addUnavailableCommand(CLI::App& app, const std::string& name, const std::string& needs,
                           int& exit_code);

#ifdef CARDEMO_HAVE_SDL
/// `cardemo play [SCENE] [--record FILE] [--replay FILE] [--json FILE]`: the game in a window.
void addPlayCommand(CLI::App& app, int& exit_code);

/// `cardemo render (SCENE|REPLAY) [--frame N] [--debug] --out FILE.png`: one frame, no display.
void addRenderCommand(CLI::App& app, int& exit_code);
#endif

#ifdef CARDEMO_HAVE_COMPARE
/// `cardemo compare REPLAY [--scene S] [--json FILE|-] [--radius R] [--all-exact]`.
void addCompareCommand(CLI::App& app, int& exit_code);

/// `cardemo compare-sweep [--pairs N] [--seed S]`: random box pairs, disagreement tables.
void addCompareSweepCommand(CLI::App& app, int& exit_code);

/// `cardemo compare-world REPLAY [--scene S]`: the same replay as a Box2D b2World.
void addCompareWorldCommand(CLI::App& app, int& exit_code);
#endif

}  // namespace cardemo::app
