#pragma once
/// Seeded random box pairs near touching, far from and near the origin, judged every way.

#include <array>
#include <cstdint>
#include <string>

#include "compare/frame_compare.hpp"

namespace cardemo::compare {

/// Distances of box A's centre from the origin that the sweep visits, metres.
inline constexpr std::array<double, 4> kSweepOffsets{0.0, 1e3, 1e5, 1e7};
/// Upper edges of the |exact separation| bins, metres (both signs: gaps and penetrations).
inline constexpr std::array<double, 5> kSweepGapEdges{1e-6, 1e-4, 1e-2, 1e-1, 1.0};

/// Options of a sweep.
struct SweepOptions {
  std::int64_t pairs = 1'000'000;  ///< Pairs in all, aimed evenly at the offsets and gap bins.
  std::uint64_t seed = 1;          ///< std::mt19937_64 seed.
  bool all_exact = false;          ///< Run the GMP oracle on every pair.
};

/// Counts for one (offset, gap bin) cell.
struct SweepCell {
  std::int64_t pairs = 0;                    ///< Pairs that landed in this cell.
  std::array<Tally, kVerdictCount> tally{};  ///< Per verdict, against exact.
};

/// The whole sweep.
struct SweepReport {
  /// cells[offset][gap bin]; a pair whose |separation| exceeds the last edge is not counted.
  std::array<std::array<SweepCell, kSweepGapEdges.size()>, kSweepOffsets.size()> cells{};
  std::int64_t pairs = 0;      ///< Pairs generated.
  std::int64_t gmp_calls = 0;  ///< Pairs that needed the GMP oracle.
  /// Largest |cardemo's separation - exact separation| over the pairs the GMP oracle judged, m.
  double max_separation_error = 0.0;
};

/// Runs the sweep: for each pair a random box A (0.1 to 20 m sides, any heading, a quarter of
/// them axis-aligned) centred at a random point at the offset's distance, and a random box B
/// moved along the SAT normal to a target signed gap, log-uniform inside a gap bin.
[[nodiscard]] SweepReport runSweep(const SweepOptions& options);

/// Markdown tables per verdict: disagree (outside the contract's |sep| <= 1e-6 m band) and
/// borderline (inside it) counts, apart, per offset and gap bin.
[[nodiscard]] std::string sweepTables(const SweepReport& report);

}  // namespace cardemo::compare
