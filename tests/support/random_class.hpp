#pragma once
/// One seeded random class of the pair-query property tests: the contract tolerances, the
/// failure collector, the statistics and the runner, shared by the 2D and 3D tests.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "test_scale.hpp"

namespace cardemo::testing {

/// Contract accuracy of the pair queries (CONTRACT.md, "Pair queries"): the hit must be right
/// when |exact sep| exceeds this, metres.
inline constexpr double kHitTolerance = 1e-6;
/// Contract bound on |sep - exact sep|, metres.
inline constexpr double kSepTolerance = 2e-6;
/// Pairs per random class at full scale (CARDEMO_TEST_SCALE scales it).
inline constexpr int kCasesPerClass = 100000;

/// Collects failures of a property over many cases and keeps the first few messages.
class Failures {
 public:
  /// Records a failure.
  void fail(int index, const std::string& what) {
    if (count_ < 5) messages_ << "case " << index << ": " << what << "\n";
    ++count_;
  }
  /// Records a failure when `ok` is false.
  void check(bool ok, int index, const std::string& what) {
    if (!ok) fail(index, what);
  }
  /// Number of failed checks.
  [[nodiscard]] int count() const { return count_; }
  /// The first failure messages.
  [[nodiscard]] std::string report() const { return messages_.str(); }

 private:
  int count_ = 0;
  std::ostringstream messages_;
};

/// Statistics of one batch of pair comparisons.
struct ClassStats {
  int cases = 0;                        ///< Pairs checked.
  int exact_hits = 0;                   ///< Pairs the oracle calls touching or overlapping.
  int borderline = 0;                   ///< Pairs with |exact sep| <= kHitTolerance.
  double max_error = 0.0;               ///< Largest |sep - exact sep| seen, metres.
  std::optional<int> edge_wins;         ///< Results on an edge-edge axis (3D), when counted.
  std::optional<double> max_asymmetry;  ///< Largest |sep(A, B) - sep(B, A)|, when measured.

  /// Counts one pair with the oracle's verdict.
  void tally(bool exact_hit, double exact_sep) {
    ++cases;
    exact_hits += exact_hit ? 1 : 0;
    borderline += std::abs(exact_sep) <= kHitTolerance ? 1 : 0;
  }
  /// Counts one result's axis: an edge-edge cross product or not.
  void countAxis(bool edge_edge) { edge_wins = edge_wins.value_or(0) + (edge_edge ? 1 : 0); }
  /// Notes |sep(A, B) - sep(B, A)| of one pair.
  void noteAsymmetry(double asym) { max_asymmetry = std::max(max_asymmetry.value_or(0.0), asym); }
};

/// Prints one class's statistics line (edge-axis wins and asymmetry where they were measured).
inline void printClassStats(const std::string& name, const ClassStats& s) {
  std::printf("[ %s ] %d pairs, %d exact hits, %d borderline", name.c_str(), s.cases, s.exact_hits,
              s.borderline);
  if (s.edge_wins) std::printf(", %d edge-axis wins", *s.edge_wins);
  std::printf(", worst |sep - exact| %.3g m", s.max_error);
  if (s.max_asymmetry) std::printf(", worst asymmetry %.3g m", *s.max_asymmetry);
  std::printf("\n");
}

/// Runs one seeded random class: scaledCount(count) calls of `one_case(rng, index, failures,
/// stats)` on a generator `Rng(seed)`, then prints the statistics and expects no failures.
template <class Rng = std::mt19937_64, class Case>
ClassStats runRandomClass(const std::string& name, std::uint64_t seed, int count,
                          const Case& one_case) {
  Rng rng(seed);
  Failures f;
  ClassStats s;
  const int n = scaledCount(count);
  for (int i = 0; i < n; ++i) one_case(rng, i, f, s);
  printClassStats(name, s);
  EXPECT_EQ(f.count(), 0) << name << "\n" << f.report();
  return s;
}

/// Name of the running test, for the statistics line.
inline std::string currentTestName() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "?";
}

}  // namespace cardemo::testing
