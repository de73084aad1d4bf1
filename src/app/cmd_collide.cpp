// `cardemo collide`: batch pair queries from a CSV file, one output row per input row.

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "app/number_text.hpp"
#include "geometry/sat_obb2.hpp"
#include "io/pair_csv.hpp"

namespace cardemo::app {
namespace {

struct CollideOptions {
  std::string pairs_path;
  int dim = 2;
};

// Large enough for tens of millions of rows, small enough that a hostile stream cannot exhaust
// memory.
constexpr std::size_t kMaxPairBytes = std::size_t{2} << 30;

int runCollideCommand(const CollideOptions& options) {
  const Parsed<std::string> text = readInputFile(options.pairs_path, kMaxPairBytes);
  if (!text.ok()) {
    std::fprintf(stderr, "%s\n", text.error().toString().c_str());
    return 2;
  }
  std::string out;
  if (options.dim == 2) {
    const auto rows = parsePairs2(text.value(), options.pairs_path);
    if (!rows.ok()) {
      std::fprintf(stderr, "%s\n", rows.error().toString().c_str());
      return 2;
    }
    out.reserve(rows.value().size() * 48);
    for (const PairRow2& row : rows.value()) {
      const SatResult2 r = collideObb2(row.a, row.b);
      out += r.hit ? "1," : "0,";
      out += numberText(r.separation) + ',' + numberText(r.normal.x()) + ',' +
             numberText(r.normal.y()) + '\n';
    }
  } else {
    const auto rows = parsePairs3(text.value(), options.pairs_path);
    if (!rows.ok()) {
      std::fprintf(stderr, "%s\n", rows.error().toString().c_str());
      return 2;
    }
    out.reserve(rows.value().size() * 64);
    for (const PairRow3& row : rows.value()) {
      const SatResult3 r = collideObb3(row.a, row.b);
      out += r.hit ? "1," : "0,";
      out += numberText(r.separation) + ',' + numberText(r.normal.x()) + ',' +
             numberText(r.normal.y()) + ',' + numberText(r.normal.z()) + ',' +
             std::to_string(r.axis_index) + '\n';
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace

void addCollideCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CollideOptions>();
  CLI::App* sub = app.add_subcommand("collide",
                                     "Pair queries from a CSV file (- for stdin). 2D rows: "
                                     "ax,ay,a_heading_deg,a_length,a_width, then "
                                     "the same for B; output hit,sep,nx,ny. 3D rows: centre x,y,z, "
                                     "quaternion w,x,y,z, sizes x,y,z for A "
                                     "then B; output hit,sep,nx,ny,nz,axis");
  sub->add_option("PAIRS", options->pairs_path, "CSV file of pairs, - for standard input")
      ->required();
  sub->add_option("--dim", options->dim, "2 or 3")->check(CLI::IsMember({2, 3}));
  sub->callback([options, &exit_code] { exit_code = runCollideCommand(*options); });
}

}  // namespace cardemo::app
