// Prints a hash of libm's sin and cos over a million seeded headings. CTest runs it with and
// without GLIBC_TUNABLES masking FMA (libm_probe.tunable_selects_another_build): the two differ
// only when glibc really switched to its SSE2 build, which is what makes the golden_cpu.* runs
// stand for a CPU without FMA.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>

#include "geometry/bit_cast.hpp"

int main() {
  std::mt19937_64 rng(1);
  std::uint64_t hash = 14695981039346656037ull;
  for (int i = 0; i < 1000000; ++i) {
    const double x = std::numbers::pi * (static_cast<double>(rng() >> 11) * 0x1p-52 - 1.0);
    for (const double v : {std::sin(x), std::cos(x)}) {
      hash = (hash ^ cardemo::bitCast<std::uint64_t>(v)) * 1099511628211ull;
    }
  }
  std::printf("%016llx\n", static_cast<unsigned long long>(hash));
  return 0;
}
