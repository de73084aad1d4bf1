// Run time against error for the car's integrators: every scheme at 30 to 480 Hz on runs with a
// closed-form answer; position error (max over the run and at its end) against the CPU time it
// takes to simulate one second. CSV on stdout or --csv FILE; scripts/plot_tradeoffs.py plots it.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include "car_reference_runs.hpp"
#include "lab/sim/car_integrators.hpp"
#include "sim/world.hpp"
#include "tradeoff_harness.hpp"

namespace cardemo::tradeoff {
namespace {

constexpr const char* kUsage =
    "usage: cardemo_tradeoff_integrators [--quick] [--csv FILE]\n"
    "Each car integrator at 30, 60, 120, 240, 480 Hz on runs with a closed-form answer.\n"
    "CSV: case,scheme,hz,seconds,steps,final_err_m,max_err_m,ns_per_step,ns_per_sim_s,is_default\n"
    "--quick: one second of simulated time and a few timing rounds (a smoke test, not for plots)\n";

struct Scheme {
  CarStepScheme integrator;  // null: the game's exact-arc RK4
  const char* name;
};

constexpr Scheme kSchemes[] = {
    {stepSemiImplicitEuler, "semi_implicit_euler"},
    {stepExplicitEuler, "explicit_euler"},
    {stepRk4, "rk4"},
    {nullptr, "arc_rk4"},
};
constexpr int kRates[] = {30, 60, 120, 240, 480};

struct Config {
  const ReferenceRun* run = nullptr;
  Scheme scheme{};
  int hz = 0;
  CarParams params;
  long steps = 0;
  double final_error = 0.0;
  double max_error = 0.0;
  double best_ns_per_step = std::numeric_limits<double>::infinity();
};

// The error run (untimed): position error against the closed form after every step.
void measureError(Config& c) {
  CarState s = c.run->start;
  for (long n = 1; n <= c.steps; ++n) {
    s = integrateCar(s, c.run->input, c.params, 1.0 / c.hz, c.scheme.integrator);
    const double err = (s.position - c.run->exact(static_cast<double>(n) / c.hz).position).norm();
    c.max_error = std::max(c.max_error, err);
    c.final_error = err;
  }
}

// One timing sample: the same run `reps` times, CPU ns per step.
double timeSample(const Config& c, long reps) {
  const double dt = 1.0 / c.hz;
  const double begin = threadCpuNs();
  for (long r = 0; r < reps; ++r) {
    CarState s = c.run->start;
    for (long n = 0; n < c.steps; ++n)
      s = integrateCar(s, c.run->input, c.params, dt, c.scheme.integrator);
    benchmark::DoNotOptimize(s);
  }
  return (threadCpuNs() - begin) / static_cast<double>(reps * c.steps);
}

int run(int argc, char** argv) {
  const HarnessOptions options = parseHarnessOptions(argc, argv, kUsage);
  const double seconds = options.quick ? 1.0 : 5.0;
  // Each sample runs about this many steps; the minimum over the rounds is kept (rounds interleave
  // the configurations so that a burst of load on the shared machine hits them all alike).
  const long steps_per_sample = options.quick ? 2000 : 200000;
  const int rounds = options.quick ? 2 : 9;

  const std::vector<ReferenceRun> runs = referenceRuns();
  const CarStepScheme default_scheme = SimulationSchemes{}.car_step;
  const double default_hz = WorldSettings{}.hz;
  std::vector<Config> configs;
  for (const ReferenceRun& r : runs) {
    for (const Scheme& scheme : kSchemes) {
      for (const int hz : kRates) {
        Config c;
        c.run = &r;
        c.scheme = scheme;
        c.hz = hz;
        c.params = r.params;
        c.steps = std::lround(seconds * hz);
        measureError(c);
        configs.push_back(c);
      }
    }
  }
  for (int round = 0; round < rounds; ++round) {
    for (Config& c : configs) {
      const long reps = std::max(1L, steps_per_sample / c.steps);
      c.best_ns_per_step = std::min(c.best_ns_per_step, timeSample(c, reps));
    }
  }

  std::ostringstream csv;
  csv << "case,scheme,hz,seconds,steps,final_err_m,max_err_m,ns_per_step,ns_per_sim_s,is_default\n";
  for (const Config& c : configs) {
    char line[320];
    std::snprintf(line, sizeof line, "%s,%s,%d,%g,%ld,%.6e,%.6e,%.3f,%.1f,%d\n",
                  c.run->name.c_str(), c.scheme.name, c.hz, seconds, c.steps, c.final_error,
                  c.max_error, c.best_ns_per_step, c.best_ns_per_step * c.hz,
                  c.scheme.integrator == default_scheme && c.hz == default_hz ? 1 : 0);
    csv << line;
  }
  writeCsv(options, csv.str(), argv[0]);
  return 0;
}

}  // namespace
}  // namespace cardemo::tradeoff

int main(int argc, char** argv) {
  return cardemo::tradeoff::run(argc, argv);
}
