// Loading: parse a generated 100,000-car scene file and build the World from it; the file alone
// through loadScene (simdjson's fast reader when built with it) and through the line-tracking
// reader that reads a file the fast one turns down. Replay: headless frames per second of the
// bundled replays (a fresh World per pass, as `cardemo replay` runs).

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bench_registry.hpp"
#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "io/scene_json.hpp"
#include "io/scene_json_lines.hpp"
#include "sim/world.hpp"

namespace cardemo::bench {
namespace {

// A generated scene file in the temporary folder, removed when the benchmark ends.
class TempScene {
 public:
  explicit TempScene(std::size_t n)
      : path_(std::filesystem::temp_directory_path() /
              ("cardemo_bench_lot_" + std::to_string(::getpid()) + "_" + std::to_string(n) +
               ".json")) {
    std::ofstream(path_) << lotSceneJson(n);
  }
  ~TempScene() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TempScene(const TempScene&) = delete;
  TempScene& operator=(const TempScene&) = delete;
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

void registerLoadSize(std::size_t n) {
  const std::string size = sizeLabel(n);
  benchmark::RegisterBenchmark(("load/scene+world/" + size + "/cardemo").c_str(),
                               [n](benchmark::State& s) {
                                 const TempScene file(n);
                                 for (auto _ : s) {
                                   Parsed<Scene> scene = loadScene(file.path());
                                   if (!scene.ok()) {
                                     s.SkipWithError(scene.error().toString().c_str());
                                     return;
                                   }
                                   const World world(std::move(scene).value());
                                   benchmark::DoNotOptimize(world.colliders().bounds().data());
                                 }
                                 s.counters["cars"] = static_cast<double>(n);
                               })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("load/scene/" + size + "/cardemo").c_str(),
                               [n](benchmark::State& s) {
                                 const TempScene file(n);
                                 for (auto _ : s) {
                                   const Parsed<Scene> scene = loadScene(file.path());
                                   benchmark::DoNotOptimize(scene.ok());
                                 }
                               })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(
      ("load/scene-lines/" + size + "/cardemo").c_str(),
      [n](benchmark::State& s) {
        const TempScene file(n);
        for (auto _ : s) {
          const Parsed<std::string> text = readInputFile(file.path(), kMaxSceneBytes);
          const Parsed<Scene> scene = parseSceneWithLines(text.value(), file.path());
          benchmark::DoNotOptimize(scene.ok());
        }
      })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("load/world/" + size + "/cardemo").c_str(),
                               [n](benchmark::State& s) {
                                 const Scene scene = lotScene(n);
                                 for (auto _ : s) {
                                   const World world(scene);
                                   benchmark::DoNotOptimize(world.colliders().bounds().data());
                                 }
                               })
      ->Unit(benchmark::kMillisecond);
}

void registerReplay(const char* name) {
  const std::string path = std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/" + name + ".replay";
  benchmark::RegisterBenchmark(
      (std::string("replay/") + name + "/cardemo").c_str(),
      [path](benchmark::State& s) {
        const Parsed<Replay> replay = loadReplay(path);
        if (!replay.ok()) {
          s.SkipWithError(replay.error().toString().c_str());
          return;
        }
        const Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
        if (!scene.ok()) {
          s.SkipWithError(scene.error().toString().c_str());
          return;
        }
        std::int64_t frames = 0;
        for (auto _ : s) {
          s.PauseTiming();
          World world(scene.value(), settingsForReplay(replay.value()));
          s.ResumeTiming();
          runReplayInputs(world, replay.value());
          frames += world.frame();
          benchmark::DoNotOptimize(world.stateHash());
        }
        s.SetItemsProcessed(frames);
        s.counters["frames_per_pass"] =
            static_cast<double>(frames / std::max<std::int64_t>(1, s.iterations()));
      })
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

void registerLoad(const BenchConfig& config) {
  registerLoadSize(config.smoke ? 1000 : 100000);
  for (const char* name : {"demo", "large-lot"}) registerReplay(name);
}

}  // namespace cardemo::bench
