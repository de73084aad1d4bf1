// `cardemo replay`: a headless run of a scripted replay, with summary, JSON, trace and
// expectations.

#include <cstdio>
#include <functional>
#include <string>

#include "app/commands.hpp"
#include "geometry/angle.hpp"
#include "io/atomic_file.hpp"
#include "io/atomic_stream.hpp"
#include "io/number_text.hpp"
#include "io/replay_runner.hpp"
#include "io/summary_json.hpp"
#include "sim/parking_readout.hpp"

namespace cardemo::app {
namespace {

struct ReplayOptions {
  std::string replay_path;
  std::string scene_path;
  std::string json_path;
  std::string trace_path;
  bool print_expect = false;
  bool bay_chain = false;
};

constexpr std::size_t kMaxHitsShown = 12;

std::string traceRow(const World& world) {
  const CarState& car = world.car();
  std::string row = std::to_string(world.frame());
  for (double v : {car.position.x(), car.position.y(), degreesOf(car.direction), car.speed,
                   degreesFromRadians(car.steer)}) {
    row += ',';
    row += numberText(v);
  }
  row +=
      ',' + std::to_string(world.health()) + ',' + std::to_string(world.contacts().size()) + '\n';
  return row;
}

std::string summaryText(const World& world, const ReplayOptions& options) {
  const Scene& scene = world.scene();
  const CarState& car = world.car();
  const WorldStats& s = world.stats();
  const double hz = world.settings().hz;
  std::string out;
  out += "replay    " + options.replay_path + "\n";
  out += "scene     " + scene.name + " (" + std::to_string(scene.parked.size()) + " parked cars, " +
         std::to_string(scene.obstacles.size()) + " obstacles" + (scene.bounds ? ", walls" : "") +
         ")\n";
  out += "frames    " + std::to_string(world.frame()) + " at " + numberText(hz) + " Hz (" +
         fixedText(static_cast<double>(world.frame()) / hz, 2) + " s)\n";
  out += "health    " + std::to_string(world.health()) + " / " +
         std::to_string(scene.player.health) + (world.gameOver() ? "  GAME OVER" : "") + "\n";
  out += "hits      " + std::to_string(world.hits().size()) + "\n";
  for (std::size_t i = 0; i < world.hits().size() && i < kMaxHitsShown; ++i) {
    const HitEvent& h = world.hits()[i];
    out += "  frame " + std::to_string(h.frame) + "  " + h.id + "  " + fixedText(h.speed, 2) +
           " m/s  -" + std::to_string(h.damage) + "\n";
  }
  if (world.hits().size() > kMaxHitsShown) {
    out += "  ... and " + std::to_string(world.hits().size() - kMaxHitsShown) + " more\n";
  }
  out += "final     x " + fixedText(car.position.x(), 3) + "  y " + fixedText(car.position.y(), 3) +
         "  heading " + fixedText(degreesOf(car.direction), 2) + " deg  speed " +
         fixedText(car.speed, 2) + " m/s\n";
  out += "hash      " + hashHex(world.stateHash()) + "\n";
  out += "work      " + std::to_string(s.broadphase_queries) + " broad-phase queries (" +
         std::to_string(s.reused_queries) + " more answered from the last one's grown box, " +
         std::to_string(s.skipped_queries) + " skipped: box unchanged), " +
         std::to_string(s.broadphase_candidates) + " candidates, " +
         std::to_string(s.narrowphase_tests) + " narrow-phase tests (" +
         std::to_string(s.skipped_tests) + " more skipped after a push-out), " +
         std::to_string(s.contacts) + " contacts, " + std::to_string(s.substeps) + " sub-steps, " +
         std::to_string(s.sweeps) + " sweeps\n";
  return out;
}

// The summary JSON, with the bay chain's when --bay-chain ran one.
nlohmann::json summaryOf(const World& world, const ParkingChallenge* goal,
                         const std::optional<BayChain>& chain) {
  nlohmann::json j = summaryJson(world, goal);
  if (chain) j["bay_chain"] = bayChainJson(*chain);
  return j;
}

std::string gatesText(const GateCourse& gates) {
  if (gates.size() == 0) return "";
  std::string out = "gates     " + std::to_string(gates.passed()) + " of " +
                    std::to_string(gates.size()) + " passed";
  if (gates.misses() > 0) out += ", " + std::to_string(gates.misses()) + " missed";
  return out + "\n";
}

// "bays      1 of 2 parked (frame 812)" for a chain of bays; nothing for one bay.
std::string baysText(const ParkingChallenge& challenge) {
  if (challenge.bays().size() < 2) return "";
  std::string out = "bays      " + std::to_string(challenge.baysParked()) + " of " +
                    std::to_string(challenge.bays().size()) + " parked";
  for (std::size_t i = 0; i < challenge.baysParked(); ++i) {
    out += (i == 0 ? " (frame " : ", ") + std::to_string(*challenge.bayParkedFrame(i));
  }
  return out + (challenge.baysParked() > 0 ? ")\n" : "\n");
}

std::string goalText(const ParkingChallenge* challenge) {
  if (challenge == nullptr) return "";
  const std::string gates = gatesText(challenge->gates()) + baysText(*challenge);
  const std::optional<std::int64_t> start = challenge->clockStart();
  if (const std::optional<ParkingScore> score = challenge->score()) {
    // The clock runs from the car's first move (frame 0 when it never moved).
    return gates + "parked    frame " + std::to_string(*challenge->parkedFrame()) + ": " +
           fixedText(score->seconds, 2) + " s from frame " + std::to_string(start.value_or(0)) +
           ", damage " + std::to_string(score->damage) + ", " + std::to_string(score->stars) +
           (score->stars == 1 ? " star\n" : " stars\n");
  }
  std::string why;
  for (const std::string& reason : notParkedReasons(*challenge)) {
    why += (why.empty() ? "" : ", ") + reason;
  }
  return gates + "parked    never (" + why + ")\n";
}

int runReplayCommand(const ReplayOptions& options) {
  const Parsed<Replay> replay = loadReplay(options.replay_path);
  if (!replay.ok()) {
    std::fprintf(stderr, "%s\n", replay.error().toString().c_str());
    return 2;
  }
  Parsed<Scene> scene = loadReplayScene(replay.value(), options.replay_path, options.scene_path);
  if (!scene.ok()) {
    std::fprintf(stderr, "%s\n", scene.error().toString().c_str());
    return 2;
  }
  World world(std::move(scene).value(), settingsForReplay(replay.value()));

  std::unique_ptr<AtomicStream> trace;
  if (!options.trace_path.empty()) {
    trace = std::make_unique<AtomicStream>(options.trace_path);
    if (!trace->error().empty()) {
      std::fprintf(stderr, "%s\n", trace->error().c_str());
      return 2;
    }
    trace->write("frame,x,y,heading_deg,speed,steer_deg,health,contacts\n");
    trace->write(traceRow(world));
  }
  std::optional<ParkingChallenge> challenge = startChallenge(world);
  std::optional<BayChain> chain;
  if (options.bay_chain) chain = startBayChain(world);
  // No trace and no goal: nothing to observe between steps, so no per-frame call at all.
  std::function<void(const World&)> after_step;
  if (trace || challenge || chain) {
    after_step = [&](const World& w) {
      if (trace) trace->write(traceRow(w));
      if (challenge) challenge->observe(w);
      if (chain) chain->observe(w);
    };
  }
  runReplayInputs(world, replay.value(), after_step);
  const ParkingChallenge* goal = challenge ? &*challenge : nullptr;
  if (trace) {
    if (std::string why = trace->commit(); !why.empty()) {
      std::fprintf(stderr, "%s\n", why.c_str());
      return 2;
    }
  }

  const bool json_to_stdout = options.json_path == "-";
  std::string summary = summaryText(world, options) + goalText(goal);
  if (chain) {
    const std::optional<std::size_t> bay = chain->current();
    summary += "bay chain " + std::to_string(chain->count()) + " parked of " +
               std::to_string(chain->bays().size()) + " free bays" +
               (bay ? ", next " + chain->bays()[*bay].id : std::string()) + "\n";
  }
  std::fputs(summary.c_str(), json_to_stdout ? stderr : stdout);
  if (!options.json_path.empty()) {
    if (std::string why =
            writeFileAtomically(options.json_path, summaryOf(world, goal, chain).dump(2) + "\n");
        !why.empty()) {
      std::fprintf(stderr, "%s\n", why.c_str());
      return 2;
    }
  }
  if (options.print_expect) {
    std::fputs(formatExpectations(expectationsOf(world, goal)).c_str(),
               json_to_stdout ? stderr : stdout);
  }

  const std::vector<std::string> diffs = checkExpectations(replay.value(), world, goal);
  FILE* report = json_to_stdout ? stderr : stdout;
  if (!diffs.empty()) {
    for (const std::string& d : diffs) std::fprintf(report, "FAILED    %s\n", d.c_str());
    return 1;
  }
  const ReplayExpectations& e = replay.value().expect;
  if (e.health || e.hit_count || e.hits || e.hash || e.frames || e.parked)
    std::fputs("expect    all met\n", report);
  return 0;
}

}  // namespace

void addReplayCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* sub =
      app.add_subcommand("replay", "Run a scripted replay headless and print a summary");
  sub->add_option("REPLAY", options->replay_path, "Replay file (cardemo-replay 1)")->required();
  sub->add_option("--scene", options->scene_path,
                  "Scene file; overrides the replay's `scene` line");
  sub->add_option("--json", options->json_path, "Write the summary JSON to FILE (- for stdout)");
  sub->add_option("--trace", options->trace_path, "Write a CSV with one row per frame to FILE");
  sub->add_flag(
      "--bay-chain", options->bay_chain,
      "Free drive's bay chain: count the free bays parked in turn (bay_chain in the JSON)");
  sub->add_flag("--print-expect", options->print_expect,
                "Print expectation lines that describe this run (to paste into the replay)");
  sub->callback([options, &exit_code] { exit_code = runReplayCommand(*options); });
}

}  // namespace cardemo::app
