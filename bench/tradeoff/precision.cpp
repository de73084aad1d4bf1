// Run time against error for the 2D OBB SAT's precision: the product's f64 collideObb2 against
// bench-local f32 and mixed kernels (sat_precision_kernels.hpp), on car-sized pairs near touching
// at world offsets 0 to 1e7 m. Errors against the GMP oracle; cost in CPU ns per pair over a batch.
// CSV on stdout or --csv FILE; scripts/plot_tradeoffs.py plots it.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "compare/exact/exact_sat.hpp"
#include "geometry/angle.hpp"
#include "geometry/sat_obb2.hpp"
#include "sat_precision_kernels.hpp"
#include "tradeoff_harness.hpp"

namespace cardemo::tradeoff {
namespace {

constexpr const char* kUsage =
    "usage: cardemo_tradeoff_precision [--quick] [--csv FILE] [--seed N]\n"
    "The 2D OBB SAT in f32 world, f32 relative, mixed, f64 (bench kernel) and f64 (the product's\n"
    "collideObb2) against the exact\n"
    "oracle, on pairs within 1e-7..1 m of touching (log spread, both signs) at world offsets\n"
    "0, 1e1, 1e3, 1e5, 1e6, 1e7 m; boxes car-sized (3.5-5.5 x 1.5-2.2 m) or large (20-100 x\n"
    "2-20 m, the contract's sizes go to 100 m).\n"
    "CSV: kernel,boxes,offset_m,pairs,borderline,hit_wrong,sep_bad,misclassified,\n"
    "     misclassified_rate,sep_err_max_m,same_bits_as_product,ns_per_pair,is_default\n"
    "--quick: a few hundred pairs per offset (a smoke test, not for plots)\n";

// The contract's accuracy (shared/CONTRACT.md, pair queries): the verdict must be right whenever
// |sep| > 1e-6 m, and sep within 2e-6 m.
constexpr double kVerdictBand = 1e-6;
constexpr double kSepTolerance = 2e-6;

using Kernel = SatResult2 (*)(const Obb2&, const Obb2&);

struct KernelInfo {
  const char* name;
  Kernel kernel;
};

constexpr KernelInfo kKernels[] = {
    {"f32_world", collideF32World}, {"f32_relative", collideF32Relative},
    {"mixed", collideMixed},        {"f64_kernel", collideF64Kernel},
    {"f64", collideObb2},  // the product's own function
};
constexpr double kOffsets[] = {0.0, 1e1, 1e3, 1e5, 1e6, 1e7};

// Box sizes: full length range and full width range, metres.
struct BoxClass {
  const char* name;
  double length_min, length_max, width_min, width_max;
};
constexpr BoxClass kBoxClasses[] = {{"car", 3.5, 5.5, 1.5, 2.2}, {"large", 20.0, 100.0, 2.0, 20.0}};

struct Pair {
  Obb2 a, b;
  exact::ExactResult truth;
};

// A box of the class's sizes with a random heading.
Obb2 randomBox(std::mt19937_64& rng, const BoxClass& sizes, const Eigen::Vector2d& centre) {
  std::uniform_real_distribution<double> length(sizes.length_min, sizes.length_max);
  std::uniform_real_distribution<double> width(sizes.width_min, sizes.width_max);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  return {centre, unitFromRadians(angle(rng)), {0.5 * length(rng), 0.5 * width(rng)}};
}

// A pair whose separation is close to `gap`: B slides along a random direction from A, Newton
// steps on the product's separation (its slope along the direction is |normal . direction|).
Pair nearTouchingPair(std::mt19937_64& rng, const BoxClass& sizes, double offset, double gap) {
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> jitter(-50.0, 50.0);
  const Eigen::Vector2d where = unitFromRadians(angle(rng)) * offset;
  Pair p;
  // y first: the order GCC took when docs/perf/precision.csv was made, now on every compiler.
  const double jitter_y = jitter(rng);
  const double jitter_x = jitter(rng);
  p.a = randomBox(rng, sizes, where + Eigen::Vector2d(jitter_x, jitter_y));
  p.b = randomBox(rng, sizes, p.a.center);
  const Eigen::Vector2d direction = unitFromRadians(angle(rng));
  double distance = p.a.half.norm() + p.b.half.norm() + gap;
  for (int i = 0; i < 8; ++i) {
    p.b.center = p.a.center + direction * distance;
    const SatResult2 r = collideObb2(p.a, p.b);
    const double slope = std::max(std::abs(r.normal.dot(direction)), 0.05);
    distance += (gap - r.separation) / slope;
  }
  p.b.center = p.a.center + direction * distance;
  p.truth = exact::collideObb2(p.a, p.b);
  return p;
}

struct Tally {
  long pairs = 0, borderline = 0, hit_wrong = 0, sep_bad = 0, misclassified = 0;
  long same_bits = 0;  // answers identical to the product's collideObb2, bit for bit
  double sep_err_max = 0.0;
  double best_ns_per_pair = std::numeric_limits<double>::infinity();
};

bool bitsEqual(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

Tally judge(const KernelInfo& k, const std::vector<Pair>& pairs) {
  Tally t;
  for (const Pair& p : pairs) {
    const SatResult2 v = k.kernel(p.a, p.b);
    const SatResult2 product = collideObb2(p.a, p.b);
    t.same_bits +=
        (v.hit == product.hit && bitsEqual(v.separation, product.separation) &&
         bitsEqual(v.normal.x(), product.normal.x()) && bitsEqual(v.normal.y(), product.normal.y()))
            ? 1
            : 0;
    const bool borderline = std::abs(p.truth.separation) <= kVerdictBand;
    const bool hit_wrong = !borderline && v.hit != p.truth.hit;
    const double err = std::abs(v.separation - p.truth.separation);
    const bool sep_bad = !(err <= kSepTolerance);
    ++t.pairs;
    t.borderline += borderline ? 1 : 0;
    t.hit_wrong += hit_wrong ? 1 : 0;
    t.sep_bad += sep_bad ? 1 : 0;
    t.misclassified += (hit_wrong || sep_bad) ? 1 : 0;
    t.sep_err_max = std::max(t.sep_err_max, err);
  }
  return t;
}

// One timing sample: the kernel over the batch `reps` times, CPU ns per pair.
double timeSample(Kernel kernel, const std::vector<Pair>& batch, long reps) {
  const double begin = threadCpuNs();
  for (long r = 0; r < reps; ++r) {
    double sum = 0.0;
    long hits = 0;
    for (const Pair& p : batch) {
      const SatResult2 v = kernel(p.a, p.b);
      sum += v.separation + v.normal.x();
      hits += v.hit ? 1 : 0;
    }
    benchmark::DoNotOptimize(sum);
    benchmark::DoNotOptimize(hits);
  }
  return (threadCpuNs() - begin) / static_cast<double>(reps * static_cast<long>(batch.size()));
}

int run(int argc, char** argv) {
  const HarnessOptions options = parseHarnessOptions(argc, argv, kUsage);
  const long pairs_per_offset = options.quick ? 400 : 40000;
  const std::size_t batch_size = options.quick ? 400 : 4096;
  const long pairs_per_sample = options.quick ? 20000 : 2000000;
  const int rounds = options.quick ? 2 : 7;

  // One set of pairs per (box class, offset), each with its own seeded generator.
  struct Set {
    const BoxClass* sizes;
    double offset;
    std::vector<Pair> pairs;
    std::vector<Tally> tallies;  // one per kernel
  };
  std::vector<Set> sets;
  for (const BoxClass& sizes : kBoxClasses) {
    for (const double offset : kOffsets) {
      std::mt19937_64 rng(options.seed * 1000003u + sets.size());
      std::uniform_real_distribution<double> exponent(-7.0, 0.0);
      std::bernoulli_distribution negative(0.5);
      Set set{&sizes, offset, {}, {}};
      set.pairs.reserve(static_cast<std::size_t>(pairs_per_offset));
      for (long i = 0; i < pairs_per_offset; ++i) {
        const double magnitude = std::pow(10.0, exponent(rng));
        set.pairs.push_back(
            nearTouchingPair(rng, sizes, offset, negative(rng) ? -magnitude : magnitude));
      }
      for (const KernelInfo& k : kKernels) set.tallies.push_back(judge(k, set.pairs));
      sets.push_back(std::move(set));
    }
  }
  for (int round = 0; round < rounds; ++round) {
    for (Set& set : sets) {
      const std::size_t n = std::min(batch_size, set.pairs.size());
      const std::vector<Pair> batch(set.pairs.begin(), set.pairs.begin() + static_cast<long>(n));
      const long reps = std::max(1L, pairs_per_sample / static_cast<long>(n));
      for (std::size_t k = 0; k < std::size(kKernels); ++k) {
        Tally& t = set.tallies[k];
        t.best_ns_per_pair =
            std::min(t.best_ns_per_pair, timeSample(kKernels[k].kernel, batch, reps));
      }
    }
  }

  std::ostringstream csv;
  csv << "kernel,boxes,offset_m,pairs,borderline,hit_wrong,sep_bad,misclassified,"
         "misclassified_rate,sep_err_max_m,same_bits_as_product,ns_per_pair,is_default\n";
  for (std::size_t k = 0; k < std::size(kKernels); ++k) {
    for (const Set& set : sets) {
      const Tally& t = set.tallies[k];
      char line[320];
      std::snprintf(line, sizeof line, "%s,%s,%g,%ld,%ld,%ld,%ld,%ld,%.6e,%.6e,%ld,%.3f,%d\n",
                    kKernels[k].name, set.sizes->name, set.offset, t.pairs, t.borderline,
                    t.hit_wrong, t.sep_bad, t.misclassified,
                    static_cast<double>(t.misclassified) / static_cast<double>(t.pairs),
                    t.sep_err_max, t.same_bits, t.best_ns_per_pair,
                    kKernels[k].kernel == collideObb2 ? 1 : 0);
      csv << line;
    }
  }
  writeCsv(options, csv.str(), argv[0]);
  return 0;
}

}  // namespace
}  // namespace cardemo::tradeoff

int main(int argc, char** argv) {
  return cardemo::tradeoff::run(argc, argv);
}
