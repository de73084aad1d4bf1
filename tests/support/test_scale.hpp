#pragma once
/// Case counts of the random property tests, scaled by CARDEMO_TEST_SCALE (CI's sanitizer stage
/// runs a tenth of them; the plain build runs the full counts).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace cardemo::testing {

/// The environment variable `name` when it is a positive finite number, else 1.
inline double envScale(const char* name) {
  const char* s = std::getenv(name);
  const double v = s != nullptr ? std::atof(s) : 1.0;
  return v > 0.0 && std::isfinite(v) ? v : 1.0;
}

/// CARDEMO_TEST_SCALE (default 1: the full counts).
inline double testScale() {
  return envScale("CARDEMO_TEST_SCALE");
}

/// `full` times testScale(), rounded down, and at least `at_least`.
inline std::int64_t scaledCases(std::int64_t full, std::int64_t at_least = 1) {
  return std::max(at_least, static_cast<std::int64_t>(static_cast<double>(full) * testScale()));
}

/// scaledCases for an int count.
inline int scaledCount(int full) {
  return static_cast<int>(scaledCases(full));
}

}  // namespace cardemo::testing
