// `cardemo collide`: batch pair queries from a CSV file, one output row per input row.

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "geometry/sat_obb2.hpp"
#include "io/number_text.hpp"
#include "io/pair_csv.hpp"

#ifdef CARDEMO_HAVE_COMPARE
#include "compare/box2d/box2d_shapes.hpp"
#include "compare/exact/exact_sat.hpp"
#endif

namespace cardemo::app {
namespace {

struct CollideOptions {
  std::string pairs_path;
  int dim = 2;
  std::vector<std::string> oracles;  // "exact", "box2d": extra columns, in that order
};

bool wants(const CollideOptions& options, const char* oracle) {
  return std::find(options.oracles.begin(), options.oracles.end(), oracle) != options.oracles.end();
}

// Extra columns for a 2D row: exact_hit,exact_sep (GMP oracle) then b2_overlap,b2_points (Box2D
// 2.4.1, float world transforms, skin 0); empty when no --oracle was given.
std::string oracleColumns2(const CollideOptions& options, const PairRow2& row) {
  std::string out;
#ifdef CARDEMO_HAVE_COMPARE
  if (wants(options, "exact")) {
    const exact::ExactResult e = exact::collideObb2(row.a, row.b);
    out += std::string(e.hit ? ",1," : ",0,") + numberText(e.separation);
  }
  if (wants(options, "box2d")) {
    const compare::Box2dVerdict v =
        compare::box2dCollide(compare::box2dBox(row.a, 0.0f), compare::box2dBox(row.b, 0.0f));
    out += std::string(v.overlap ? ",1," : ",0,") + std::to_string(v.points);
  }
#else
  (void)options;
  (void)row;
#endif
  return out;
}

// Extra columns for a 3D row: exact_hit,exact_sep.
std::string oracleColumns3(const CollideOptions& options, const PairRow3& row) {
  std::string out;
#ifdef CARDEMO_HAVE_COMPARE
  if (wants(options, "exact")) {
    const exact::ExactResult e = exact::collideObb3(row.a, row.b);
    out += std::string(e.hit ? ",1," : ",0,") + numberText(e.separation);
  }
#else
  (void)options;
  (void)row;
#endif
  return out;
}

// Large enough for tens of millions of rows, small enough that a hostile stream cannot exhaust
// memory.
constexpr std::size_t kMaxPairBytes = std::size_t{2} << 30;

int runCollideCommand(const CollideOptions& options) {
#ifndef CARDEMO_HAVE_COMPARE
  if (!options.oracles.empty()) {
    std::fprintf(stderr, "cardemo: --oracle needs the comparison build (install libbox2d-dev)\n");
    return 2;
  }
#endif
  if (options.dim == 3 && wants(options, "box2d")) {
    std::fprintf(stderr, "cardemo: collide --oracle box2d works with --dim 2 only\n");
    return 2;
  }
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
             numberText(r.normal.y()) + oracleColumns2(options, row) + '\n';
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
             std::to_string(r.axis_index) + oracleColumns3(options, row) + '\n';
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
#ifdef CARDEMO_HAVE_COMPARE
  sub->add_option("--oracle", options->oracles,
                  "Extra columns (repeat or comma list): exact -> exact_hit,exact_sep (GMP "
                  "oracle); box2d -> b2_overlap,b2_points (Box2D 2.4.1, skin 0; 2D only)")
      ->delimiter(',')
      ->check(CLI::IsMember({"exact", "box2d"}));
#endif
  sub->callback([options, &exit_code] { exit_code = runCollideCommand(*options); });
}

}  // namespace cardemo::app
