// `cardemo compare-world`: the replay run by our World and by a Box2D b2World side by side.

#ifdef CARDEMO_HAVE_COMPARE

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "compare/world_compare.hpp"

namespace cardemo::app {

void addCompareWorldCommand(CLI::App& app, int& exit_code) {
  auto replay_path = std::make_shared<std::string>();
  auto scene_path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "compare-world",
      "Run a replay through our World and a Box2D b2World driven by the same velocities: hit "
      "frames, begin-contact lag, where the solver stops, the speed clamp");
  sub->add_option("REPLAY", *replay_path, "Replay file (cardemo-replay 1)")->required();
  sub->add_option("--scene", *scene_path, "Scene file; overrides the replay's `scene` line");
  sub->callback([replay_path, scene_path, &exit_code] {
    const Parsed<compare::WorldComparison> result =
        compare::compareWorld(*replay_path, *scene_path);
    if (!result.ok()) {
      std::fprintf(stderr, "%s\n", result.error().toString().c_str());
      exit_code = 2;
      return;
    }
    std::fputs(compare::worldComparisonText(result.value()).c_str(), stdout);
    exit_code = 0;
  });
}

}  // namespace cardemo::app

#endif  // CARDEMO_HAVE_COMPARE
