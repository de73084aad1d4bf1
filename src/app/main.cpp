/// cardemo: entry point; wires the subcommands together.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "app/commands.hpp"

namespace {

// Builds the command line and runs the chosen subcommand; its exceptions are handled by main.
int run(int argc, char** argv) {
  CLI::App app{"cardemo: a top-down car game with an exact, fast collision core", "cardemo"};
  app.set_version_flag("--version", std::string("cardemo ") + CARDEMO_VERSION);
  app.require_subcommand(1);
  int exit_code = 0;
  cardemo::app::addReplayCommand(app, exit_code);
  cardemo::app::addCollideCommand(app, exit_code);
#ifdef CARDEMO_HAVE_COMPARE
  cardemo::app::addCompareCommand(app, exit_code);
  cardemo::app::addCompareSweepCommand(app, exit_code);
  cardemo::app::addCompareWorldCommand(app, exit_code);
#else
  for (const char* name : {"compare", "compare-sweep", "compare-world"}) {
    cardemo::app::addUnavailableCommand(app, name, "the comparison library: Box2D 2.4 and GMP",
                                        exit_code);
  }
#endif
#ifdef CARDEMO_HAVE_SDL
  cardemo::app::addPlayCommand(app, exit_code);
  cardemo::app::addRenderCommand(app, exit_code);
#else
  cardemo::app::addUnavailableCommand(app, "play", "SDL2: a window", exit_code);
  cardemo::app::addUnavailableCommand(app, "render", "SDL2 and SDL2_image: PNG output", exit_code);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors are bad input: one line on stderr, exit status 2 (CONTRACT.md).
    std::fprintf(stderr, "cardemo: %s (see cardemo --help)\n", e.what());
    return 2;
  }
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  // Setting up the command line can throw too (allocation), so everything runs inside the try.
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cardemo: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "cardemo: internal error: unknown exception\n");
  }
  return 3;
}
