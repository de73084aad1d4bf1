// cardemo_bench: the whole suite in one executable. `--smoke` (before any Google Benchmark flag)
// selects small sizes for the CTest smoke run; every other flag goes to Google Benchmark.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_registry.hpp"
#include "geometry/batch_path.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include <box2d/b2_common.h>
#endif

namespace cardemo::bench {

std::string sizeLabel(std::size_t n) {
  if (n >= 1000000 && n % 1000000 == 0) return std::to_string(n / 1000000) + "M";
  if (n >= 1000 && n % 1000 == 0) return std::to_string(n / 1000) + "k";
  return std::to_string(n);
}

}  // namespace cardemo::bench

int main(int argc, char** argv) {
  cardemo::bench::BenchConfig config;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--smoke") == 0) {
      config.smoke = true;
    } else {
      args.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(args.size());
  benchmark::AddCustomContext("batch_path", cardemo::batchPathName(cardemo::batchPath()));
  benchmark::AddCustomContext(
      "avx2_available", cardemo::batchPathAvailable(cardemo::BatchPath::kAvx2) ? "yes" : "no");
  benchmark::AddCustomContext(
      "avx512_available", cardemo::batchPathAvailable(cardemo::BatchPath::kAvx512) ? "yes" : "no");
  benchmark::AddCustomContext("build_type", CARDEMO_BUILD_TYPE);
  benchmark::AddCustomContext("cxx_flags", CARDEMO_CXX_FLAGS);
  benchmark::AddCustomContext("isa_flags", CARDEMO_ISA_FLAGS);
  benchmark::AddCustomContext("compiler", CARDEMO_COMPILER);
#if defined(CARDEMO_HAVE_COMPARE)
  // b2_version is the linked library's own (b2_settings.cpp), not the header's.
  benchmark::AddCustomContext(
      "box2d", std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
                   std::to_string(b2_version.revision) + ", float world transforms, skin 0");
#else
  benchmark::AddCustomContext("box2d", "not built");
#endif
  cardemo::bench::registerNarrow(config);
  cardemo::bench::registerBatch(config);
  cardemo::bench::registerBroad(config);
  cardemo::bench::registerStep(config);
  cardemo::bench::registerOffset(config);
  cardemo::bench::registerLoad(config);
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
