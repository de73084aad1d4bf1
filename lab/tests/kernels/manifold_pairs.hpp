#pragma once
/// Random box pairs for the manifold tests: extreme sizes, any overlap, and a share exactly
/// touching face to face.

#include <utility>

#include "geometry/obb2.hpp"
#include "tests/geometry/random_cases2.hpp"

namespace cardemo::testing {

/// Pair number `index` of a seeded sequence, around a point up to `offset` metres from the origin:
/// two boxes of extreme sizes, B placed anywhere within 1.2 times their reach; every fourth pair
/// axis-aligned and exactly touching along a face, where ties decide.
inline std::pair<Obb2, Obb2> manifoldPair(Random& rng, double offset, int index) {
  const Eigen::Vector2d base = rng.offset(0.0, offset);
  const Obb2 a = rng.extremeBox(base);
  Obb2 b = rng.extremeBox(base);
  b.center += rng.offset(0.0, 1.2 * (a.half.norm() + b.half.norm()));
  if (index % 4 == 0) {
    b.axis = rng.integer(0, 1) == 0 ? a.axis : a.perp();
    b.center = a.center + a.axis * (a.half.x() + b.half.x()) * rng.sign();
  }
  return {a, b};
}

}  // namespace cardemo::testing
