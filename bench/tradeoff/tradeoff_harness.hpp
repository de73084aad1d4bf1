#pragma once
// What every run-time-against-error harness of this folder shares: the command line
// (--quick, --csv FILE, --seed N), CPU-time measurement and the CSV sink.

#include <time.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace cardemo::tradeoff {

/// Options common to the harnesses.
struct HarnessOptions {
  bool quick = false;      ///< A run of a second or two (the CTest smoke test), not for plots.
  std::string csv_path;    ///< Where the CSV goes; empty for stdout.
  std::uint64_t seed = 1;  ///< Seed of any random cases.
};

/// Parses argv; on --help prints `usage` and exits 0, on a bad argument prints one line and
/// exits 2.
inline HarnessOptions parseHarnessOptions(int argc, char** argv, const char* usage) {
  HarnessOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      o.quick = true;
    } else if (arg == "--help" || arg == "-h") {
      std::printf("%s", usage);
      std::exit(0);
    } else if ((arg == "--csv" || arg == "--seed") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--csv") {
        o.csv_path = value;
      } else {
        char* end = nullptr;
        o.seed = std::strtoull(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || value[0] == '-') {
          std::fprintf(stderr, "%s: --seed: '%s' is not a non-negative integer\n", argv[0],
                       value.c_str());
          std::exit(2);
        }
      }
    } else {
      std::fprintf(stderr, "%s: unknown or incomplete option '%s' (see --help)\n", argv[0],
                   arg.c_str());
      std::exit(2);
    }
  }
  return o;
}

/// CPU time of this thread, nanoseconds (not wall time: other processes do not count).
inline double threadCpuNs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

/// Writes the CSV text to the file (or stdout); on failure prints one line and exits 2.
inline void writeCsv(const HarnessOptions& o, const std::string& text, const char* program) {
  if (o.csv_path.empty()) {
    std::cout << text << std::flush;
    return;
  }
  std::ofstream out(o.csv_path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    std::fprintf(stderr, "%s: cannot write '%s'\n", program, o.csv_path.c_str());
    std::exit(2);
  }
}

}  // namespace cardemo::tradeoff
