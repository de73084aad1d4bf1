// Running a replay through the frame comparer, and its JSON and text reports.

#include "compare/replay_compare.hpp"

#include <algorithm>
#include <cstdio>

#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"

namespace cardemo::compare {
namespace {

constexpr std::array<Verdict, kVerdictCount> kAll{Verdict::kOurs,
                                                  Verdict::kBox2d,
                                                  Verdict::kBox2dOverlap,
                                                  Verdict::kBox2dSkin,
                                                  Verdict::kBox2dSkinOverlap,
                                                  Verdict::kExact};

nlohmann::json tallyJson(const Tally& t) {
  return {{"agree", t.agree}, {"disagree", t.disagree}, {"borderline", t.borderline}};
}

nlohmann::json hitsJson(const CompareReport& report, const VerdictRecord& r) {
  nlohmann::json hits = nlohmann::json::array();
  for (const FirstContact& h : r.hits)
    hits.push_back({{"frame", h.frame}, {"id", report.ids[h.collider]}});
  return hits;
}

std::string sepText(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", v);
  return buffer;
}

}  // namespace

Parsed<ReplayComparison> compareReplay(const std::string& replay_path,
                                       const std::string& scene_override,
                                       const CompareOptions& options,
                                       const std::function<void(std::size_t)>& on_loaded) {
  Parsed<Replay> replay = loadReplay(replay_path);
  if (!replay.ok()) return replay.error();
  Parsed<Scene> scene = loadReplayScene(replay.value(), replay_path, scene_override);
  if (!scene.ok()) return scene.error();
  World world(std::move(scene).value(), settingsForReplay(replay.value()));
  if (on_loaded) on_loaded(world.colliders().size());
  FrameComparer comparer(world, options);
  runReplayInputs(world, replay.value(), [&](const World& w) { comparer.check(w); });
  return ReplayComparison{comparer.report(), world.scene().name, world.colliders().size(),
                          world.scene().bounds ? kWallCount : 0};
}

nlohmann::json comparisonJson(const CompareReport& report) {
  nlohmann::json j;
  j["frames"] = report.frames;
  j["pairs_checked"] = report.pairs_checked;
  // The contract's `exact` object: how cardemo's verdict agrees with the exact oracle.
  j["exact"] = tallyJson(report[Verdict::kOurs].tally);
  for (Verdict v : kAll) {
    if (v == Verdict::kExact) continue;
    const VerdictRecord& r = report[v];
    nlohmann::json o = tallyJson(r.tally);
    o["hits"] = hitsJson(report, r);
    j[verdictKey(v)] = std::move(o);
  }
  j["exact_hits"] = hitsJson(report, report[Verdict::kExact]);
  j["gmp_calls"] = report.gmp_calls;
  if (report.radius) j["radius"] = *report.radius;
  return j;
}

std::size_t hitDifferences(const CompareReport& report, Verdict v) {
  const auto& mine = report[v].hits;
  const auto& exact = report[Verdict::kExact].hits;
  std::size_t diff = 0;
  for (const FirstContact& h : mine)
    diff += std::find(exact.begin(), exact.end(), h) == exact.end();
  for (const FirstContact& h : exact) diff += std::find(mine.begin(), mine.end(), h) == mine.end();
  return diff;
}

std::string comparisonText(const ReplayComparison& c) {
  const CompareReport& r = c.report;
  std::string out;
  out += "scene     " + c.scene_name + " (" + std::to_string(c.colliders) + " colliders" +
         (c.walls > 0 ? " and the " + std::to_string(c.walls) + " walls of its bounds" : "") +
         ")\n";
  out += "frames    " + std::to_string(r.frames) + " (+ frame 0)\n";
  out += "pairs     " + std::to_string(r.pairs_checked) + " checked";
  out += r.radius ? " (only colliders within " + sepText(*r.radius) + " m of the player)" : "";
  out += ", " + std::to_string(r.gmp_calls) + " by the GMP oracle\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-20s %12s %10s %10s %6s %9s\n", "verdict vs exact", "agree",
                "disagree", "borderline", "hits", "hit diffs");
  out += line;
  for (Verdict v : kAll) {
    const VerdictRecord& rec = r[v];
    std::snprintf(
        line, sizeof line, "%-20s %12lld %10lld %10lld %6zu %9zu\n", verdictKey(v),
        static_cast<long long>(rec.tally.agree), static_cast<long long>(rec.tally.disagree),
        static_cast<long long>(rec.tally.borderline), rec.hits.size(), hitDifferences(r, v));
    out += line;
  }
  for (Verdict v : kAll) {
    for (std::size_t i = 0; i < r[v].borderline_pairs.size() && i < 3; ++i) {
      const Disagreement& d = r[v].borderline_pairs[i];
      out += "borderline " + std::string(verdictKey(v)) + "  frame " + std::to_string(d.frame) +
             "  " + r.ids[d.collider] + "  says " + (d.verdict ? "hit" : "miss") +
             ", exact separation " + sepText(d.exact_separation) + " m\n";
    }
  }
  for (Verdict v : kAll) {
    for (const Disagreement& d : r[v].examples) {
      out += "disagree  " + std::string(verdictKey(v)) + "  frame " + std::to_string(d.frame) +
             "  " + r.ids[d.collider] + "  says " + (d.verdict ? "hit" : "miss") +
             ", exact separation " + sepText(d.exact_separation) + " m\n";
    }
  }
  return out;
}

}  // namespace cardemo::compare
