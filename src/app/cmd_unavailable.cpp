// Subcommands that this build leaves out (the browser build, or a build without SDL or Box2D):
// hidden from --help, they say what they need instead of CLI11's "argument was not expected".

#include <cstdio>
#include <string>

#include "app/commands.hpp"

namespace cardemo::app {

void addUnavailableCommand(CLI::App& app, const std::string& name, const std::string& needs,
                           int& exit_code) {
  CLI::App* sub = app.add_subcommand(name, "");
  sub->group("");  // not listed by --help
  sub->set_help_flag();
  sub->allow_extras();
  sub->callback([name, needs, &exit_code] {
    std::fprintf(stderr, "cardemo: %s is not available in this build (it needs %s)\n", name.c_str(),
                 needs.c_str());
    exit_code = 2;
  });
}

}  // namespace cardemo::app
