// `cardemo compare`: a replay run headless and checked frame by frame against the exact oracle
// and Box2D 2.4.1. Built only with the optional comparison library.

#ifdef CARDEMO_HAVE_COMPARE

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "compare/replay_compare.hpp"
#include "io/atomic_file.hpp"

namespace cardemo::app {
namespace {

struct CompareCommandOptions {
  std::string replay_path;
  std::string scene_path;
  std::string json_path;
  double radius = 0.0;
  bool have_radius = false;
  bool all_exact = false;
};

// Above this many colliders a full comparison takes a while; --radius makes it quick.
constexpr std::size_t kSlowColliders = 2000;

int runCompareCommand(const CompareCommandOptions& options) {
  compare::CompareOptions co;
  if (options.have_radius) co.radius = options.radius;
  co.all_exact = options.all_exact;
  const Parsed<compare::ReplayComparison> result =
      compare::compareReplay(options.replay_path, options.scene_path, co, [&](std::size_t n) {
        if (!options.have_radius && n > kSlowColliders)
          std::fprintf(stderr,
                       "cardemo: %zu colliders checked every frame; this is slow, --radius 10 "
                       "checks only those near the player\n",
                       n);
      });
  if (!result.ok()) {
    std::fprintf(stderr, "%s\n", result.error().toString().c_str());
    return 2;
  }
  const compare::CompareReport& report = result.value().report;
  const bool json_to_stdout = options.json_path == "-";
  std::fputs(compare::comparisonText(result.value()).c_str(), json_to_stdout ? stderr : stdout);
  if (!options.json_path.empty()) {
    const std::string json = compare::comparisonJson(report).dump(2) + "\n";
    if (json_to_stdout) {
      std::fputs(json.c_str(), stdout);
    } else if (std::string why = writeFileAtomically(options.json_path, json); !why.empty()) {
      std::fprintf(stderr, "%s\n", why.c_str());
      return 2;
    }
  }
  return compare::compareExitStatus(report);
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CompareCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Run a replay headless and check every frame's player-collider pairs against the exact "
      "oracle and Box2D 2.4.1; exit 1 if cardemo disagrees with the exact oracle");
  sub->add_option("REPLAY", options->replay_path, "Replay file (cardemo-replay 1)")->required();
  sub->add_option("--scene", options->scene_path,
                  "Scene file; overrides the replay's `scene` line");
  sub->add_option("--json", options->json_path, "Write the comparison JSON to FILE (- for stdout)");
  sub->add_option("--radius", options->radius,
                  "Check only colliders whose bounding box is within R metres of the player's")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag("--all-exact", options->all_exact,
                "Run the GMP oracle on every pair, even far from touching");
  sub->callback([options, sub, &exit_code] {
    options->have_radius = sub->count("--radius") > 0;
    exit_code = runCompareCommand(*options);
  });
}

}  // namespace cardemo::app

#endif  // CARDEMO_HAVE_COMPARE
