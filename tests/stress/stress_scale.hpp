#pragma once
/// Case counts and run lengths of the stress suite, scaled by CARDEMO_STRESS_SCALE.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "../support/test_scale.hpp"

namespace cardemo::stress {

/// CARDEMO_STRESS_SCALE (default 1: the short form CI runs; scripts/stress.sh uses 100).
inline double stressScale() {
  return testing::envScale("CARDEMO_STRESS_SCALE");
}

/// `n` scaled by stressScale(), at least 1 and at most `cap`.
inline std::int64_t scaled(std::int64_t n, std::int64_t cap = INT64_MAX) {
  const double m = std::round(static_cast<double>(n) * stressScale());
  return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::min(m, 9e18)), 1, cap);
}

}  // namespace cardemo::stress
