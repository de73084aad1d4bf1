// `cardemo compare-sweep`: seeded random box pairs near touching, judged by cardemo, the exact
// oracle and Box2D; prints the disagreement tables of docs/box2d-comparison.md.

#ifdef CARDEMO_HAVE_COMPARE

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "compare/pair_sweep.hpp"

namespace cardemo::app {

void addCompareSweepCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<compare::SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare-sweep",
      "Random 2D box pairs near touching at 0, 1e3, 1e5 and 1e7 m from the origin: disagreement "
      "tables of cardemo and Box2D against the exact oracle (exit 1 if cardemo disagrees)");
  sub->add_option("--pairs", options->pairs, "Number of pairs (default 1000000)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--seed", options->seed, "Random seed (default 1)");
  sub->add_flag("--all-exact", options->all_exact,
                "Run the GMP oracle on every pair, even far from touching");
  sub->callback([options, &exit_code] {
    const compare::SweepReport report = compare::runSweep(*options);
    std::printf(
        "pairs %lld, seed %llu, GMP oracle on %lld%s\n", static_cast<long long>(report.pairs),
        static_cast<unsigned long long>(options->seed), static_cast<long long>(report.gmp_calls),
        options->all_exact ? " (--all-exact)" : "");
    std::fputs(compare::sweepTables(report).c_str(), stdout);
    std::int64_t ours = 0;
    for (const auto& row : report.cells)
      for (const compare::SweepCell& cell : row)
        ours += cell.tally[static_cast<std::size_t>(compare::Verdict::kOurs)].disagree;
    exit_code = ours > 0 ? 1 : 0;
  });
}

}  // namespace cardemo::app

#endif  // CARDEMO_HAVE_COMPARE
