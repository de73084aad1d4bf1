#pragma once
/// Random draws shared by the 2D and 3D property-test generators, on std::mt19937_64.

#include <cmath>
#include <random>

namespace cardemo::testing {

/// Uniform in [lo, hi).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// Log-uniform in [lo, hi), lo > 0.
inline double logUniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}

/// Uniform integer in [lo, hi].
inline int uniformInt(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

/// +1 or -1 with equal odds, from the lowest bit of one draw.
inline double randomSign(std::mt19937_64& rng) {
  return (rng() & 1) != 0 ? 1.0 : -1.0;
}

}  // namespace cardemo::testing
