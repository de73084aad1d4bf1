#pragma once
/// The subcommands of the `cardemo` executable. Each registers itself on the CLI11 app and, when
/// chosen, stores its exit status (0 ok, 1 a check failed, 2 bad input) in `exit_code`.

#include <CLI/CLI.hpp>

namespace cardemo::app {

/// `cardemo replay REPLAY [--scene S] [--json FILE|-] [--trace FILE] [--print-expect]`.
void addReplayCommand(CLI::App& app, int& exit_code);

/// `cardemo collide PAIRS [--dim 2|3]`.
void addCollideCommand(CLI::App& app, int& exit_code);

}  // namespace cardemo::app
