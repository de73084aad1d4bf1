// The comparison engine on every bundled replay: cardemo never disagrees with the exact oracle,
// and Box2D (skin 0) agrees with it outside the tolerance and on every hit, frame for frame.

#include "compare/replay_compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace cardemo::compare {
namespace {

std::vector<std::string> bundledReplays() {
  std::vector<std::string> out;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(CARDEMO_SOURCE_DIR) + "/assets/replays"))
    if (e.path().extension() == ".replay") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool isBorderlineAt(const VerdictRecord& r, std::int64_t frame, std::uint32_t collider) {
  return std::any_of(
      r.borderline_pairs.begin(), r.borderline_pairs.end(),
      [&](const Disagreement& d) { return d.frame == frame && d.collider == collider; });
}

// A hit in one list and not the other needs the verdicts to differ at that frame or the one
// before; since Box2D never disagrees outside the tolerance here, that difference must be a
// borderline pair.
std::size_t unexplainedHitDifferences(const CompareReport& report, Verdict v) {
  const VerdictRecord& mine = report[v];
  const auto& exact = report[Verdict::kExact].hits;
  std::size_t unexplained = 0;
  auto check = [&](const FirstContact& h) {
    if (!isBorderlineAt(mine, h.frame, h.collider) &&
        !isBorderlineAt(mine, h.frame - 1, h.collider))
      ++unexplained;
  };
  for (const FirstContact& h : mine.hits)
    if (std::find(exact.begin(), exact.end(), h) == exact.end()) check(h);
  for (const FirstContact& h : exact)
    if (std::find(mine.hits.begin(), mine.hits.end(), h) == mine.hits.end()) check(h);
  return unexplained;
}

TEST(ReplayCompare, EveryBundledReplay) {
  const std::vector<std::string> replays = bundledReplays();
  ASSERT_GE(replays.size(), 8u);
  for (const std::string& path : replays) {
    SCOPED_TRACE(path);
    CompareOptions options;
    // The 10,100-car lot is checked within 10 m of the player (its far cars are never close).
    if (path.find("large-lot") != std::string::npos) options.radius = 10.0;
    const Parsed<ReplayComparison> c = compareReplay(path, "", options);
    ASSERT_TRUE(c.ok()) << c.error().toString();
    const CompareReport& r = c.value().report;
    EXPECT_GT(r.pairs_checked, 0);
    // cardemo against the exact oracle: no disagreement at all, not even borderline.
    EXPECT_EQ(r[Verdict::kOurs].tally.disagree, 0);
    EXPECT_EQ(r[Verdict::kOurs].tally.borderline, 0);
    EXPECT_EQ(r[Verdict::kOurs].hits, r[Verdict::kExact].hits);
    // Box2D with skin 0 (both queries): never wrong outside the contract's tolerance, and the same
    // hits as the oracle, frame for frame. cardemo's resting contacts keep 0.1 mm of penetration,
    // well above float resolution at these coordinates, so Box2D sees them steadily too.
    for (Verdict v : {Verdict::kBox2d, Verdict::kBox2dOverlap}) {
      EXPECT_EQ(r[v].tally.disagree, 0) << verdictKey(v);
      EXPECT_EQ(unexplainedHitDifferences(r, v), 0u) << verdictKey(v);
      EXPECT_EQ(r[v].hits, r[Verdict::kExact].hits) << verdictKey(v);
      std::printf("%-28s %-14s hits %3zu (exact %3zu), differing %zu, borderline pairs %lld\n",
                  std::filesystem::path(path).filename().c_str(), verdictKey(v), r[v].hits.size(),
                  r[Verdict::kExact].hits.size(), hitDifferences(r, v),
                  static_cast<long long>(r[v].tally.borderline));
    }
  }
}

TEST(ReplayCompare, AllExactMatchesShortcut) {
  const std::string path = std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/scrape.replay";
  CompareOptions all;
  all.all_exact = true;
  const Parsed<ReplayComparison> full = compareReplay(path, "", all);
  const Parsed<ReplayComparison> quick = compareReplay(path, "", {});
  ASSERT_TRUE(full.ok());
  ASSERT_TRUE(quick.ok());
  EXPECT_EQ(full.value().report.gmp_calls, full.value().report.pairs_checked);
  EXPECT_LT(quick.value().report.gmp_calls, quick.value().report.pairs_checked);
  for (int k = 0; k < kVerdictCount; ++k) {
    const auto v = static_cast<Verdict>(k);
    EXPECT_EQ(full.value().report[v].hits, quick.value().report[v].hits) << verdictKey(v);
    EXPECT_EQ(full.value().report[v].tally.disagree, quick.value().report[v].tally.disagree);
  }
}

TEST(ReplayCompare, RadiusNarrowsThePairs) {
  const std::string path = std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/demo.replay";
  CompareOptions near;
  near.radius = 5.0;
  const Parsed<ReplayComparison> all = compareReplay(path, "", {});
  const Parsed<ReplayComparison> some = compareReplay(path, "", near);
  ASSERT_TRUE(all.ok());
  ASSERT_TRUE(some.ok());
  EXPECT_LT(some.value().report.pairs_checked, all.value().report.pairs_checked);
  EXPECT_EQ(some.value().report[Verdict::kExact].hits, all.value().report[Verdict::kExact].hits);
  EXPECT_EQ(comparisonJson(some.value().report)["radius"], 5.0);
  EXPECT_FALSE(comparisonJson(all.value().report).contains("radius"));
}

TEST(ReplayCompare, BadInputIsAnError) {
  const Parsed<ReplayComparison> c = compareReplay("/nonexistent/x.replay", "", {});
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().toString().find("/nonexistent/x.replay"), std::string::npos);
}

TEST(ReplayCompare, ExitStatusFailsOnlyWhenCardemoDisagrees) {
  CompareReport report;
  EXPECT_EQ(compareExitStatus(report), 0);
  report[Verdict::kBox2d].tally.disagree = 7;   // Box2D being wrong is a finding
  report[Verdict::kOurs].tally.borderline = 3;  // within the contract's tolerance
  EXPECT_EQ(compareExitStatus(report), 0);
  report[Verdict::kOurs].tally.disagree = 1;
  EXPECT_EQ(compareExitStatus(report), 1);
}

}  // namespace
}  // namespace cardemo::compare
