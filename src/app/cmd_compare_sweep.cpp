// `cardemo compare-sweep`: seeded random box pairs near touching, judged by cardemo, the exact
// oracle and Box2D; prints the disagreement tables of docs/box2d-comparison.md.

#ifdef CARDEMO_HAVE_COMPARE

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "compare/pair_sweep.hpp"
#include "io/atomic_file.hpp"

namespace cardemo::app {
namespace {

// One row per (offset, gap bin, verdict): what scripts/plot_box2d_offsets.py reads.
std::string sweepCsv(const compare::SweepReport& report) {
  std::string out = "offset_m,gap_lo_m,gap_hi_m,verdict,pairs,disagree,borderline\n";
  char buffer[160];
  for (std::size_t o = 0; o < compare::kSweepOffsets.size(); ++o) {
    double lo = 0.0;
    for (std::size_t b = 0; b < compare::kSweepGapEdges.size(); ++b) {
      const compare::SweepCell& cell = report.cells[o][b];
      for (int k = 0; k < compare::kVerdictCount; ++k) {
        const auto v = static_cast<compare::Verdict>(k);
        if (v == compare::Verdict::kExact) continue;
        const compare::Tally& t = cell.tally[static_cast<std::size_t>(k)];
        std::snprintf(buffer, sizeof buffer, "%g,%g,%g,%s,%lld,%lld,%lld\n",
                      compare::kSweepOffsets[o], lo, compare::kSweepGapEdges[b],
                      compare::verdictKey(v), static_cast<long long>(cell.pairs),
                      static_cast<long long>(t.disagree), static_cast<long long>(t.borderline));
        out += buffer;
      }
      lo = compare::kSweepGapEdges[b];
    }
  }
  return out;
}

}  // namespace

void addCompareSweepCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<compare::SweepOptions>();
  auto csv_path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "compare-sweep",
      "Random 2D box pairs near touching at 0, 1e3, 1e5 and 1e7 m from the origin: disagreement "
      "tables of cardemo and Box2D against the exact oracle (exit 1 if cardemo disagrees)");
  sub->add_option("--pairs", options->pairs, "Number of pairs (default 1000000)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--seed", options->seed, "Random seed (default 1)");
  sub->add_flag("--all-exact", options->all_exact,
                "Run the GMP oracle on every pair, even far from touching");
  sub->add_option("--csv", *csv_path,
                  "Also write offset,gap,verdict,pairs,disagree,borderline rows to FILE");
  sub->callback([options, csv_path, &exit_code] {
    const compare::SweepReport report = compare::runSweep(*options);
    std::printf(
        "pairs %lld, seed %llu, GMP oracle on %lld%s; largest |cardemo - exact| "
        "separation over those: %.3g m\n",
        static_cast<long long>(report.pairs), static_cast<unsigned long long>(options->seed),
        static_cast<long long>(report.gmp_calls),
        options->all_exact ? " (--all-exact: every pair)" : "", report.max_separation_error);
    std::fputs(compare::sweepTables(report).c_str(), stdout);
    std::int64_t ours = 0;
    for (const auto& row : report.cells)
      for (const compare::SweepCell& cell : row)
        ours += cell.tally[static_cast<std::size_t>(compare::Verdict::kOurs)].disagree;
    exit_code = ours > 0 ? 1 : 0;
    if (!csv_path->empty()) {
      if (std::string why = writeFileAtomically(*csv_path, sweepCsv(report)); !why.empty()) {
        std::fprintf(stderr, "%s\n", why.c_str());
        exit_code = 2;
      }
    }
  });
}

}  // namespace cardemo::app

#endif  // CARDEMO_HAVE_COMPARE
