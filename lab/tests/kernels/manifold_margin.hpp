#pragma once
/// The face-choice margin of the contact manifold's hysteresis, written out for the tests.

#include <cmath>

#include "lab/kernels/manifold2.hpp"

namespace cardemo::testing {

/// How much better (m) a new reference face must be than the kept one before the manifold switches.
/// For penetration (< 0) this is Box2D 2.1's k_relativeTol * sepA + k_absoluteTol rearranged;
/// written with |separation| so that it also asks for a positive margin when apart.
inline double manifoldMargin(const ManifoldSettings& s, double separation) {
  return (1.0 - s.relative_tolerance) * std::abs(separation) + s.absolute_tolerance;
}

}  // namespace cardemo::testing
