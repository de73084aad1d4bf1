// No NaN or infinity leaves the lab's 2D box queries for finite input (tests/stress's generator of
// boxes over the whole finite double range): the contact manifold and the rotation-proof box.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "lab/kernels/manifold2.hpp"
#include "lab/sim/collision_schemes.hpp"
#include "tests/stress/extremes.hpp"
#include "tests/stress/stress_scale.hpp"

namespace cardemo::stress {
namespace {

using testing::Extremes;

TEST(FiniteOutput, Manifolds2dAndRotationProofBoxes) {
  Extremes x(0xf1a1);
  const std::int64_t n = scaled(200000);
  int failures = 0;
  for (std::int64_t k = 0; k < n && failures < 5; ++k) {
    const Obb2 a = x.box();
    const Obb2 b = x.boxNear(a);
    const Aabb2 wide = rotationProofBox(a);
    bool ok = wide.min.allFinite() && wide.max.allFinite();
    const Manifold2 m = manifoldObb2(a, b);
    ok = ok && m.normal.allFinite() && m.count >= 0 && m.count <= 2;
    for (int i = 0; i < m.count; ++i) {
      ok = ok && m.points[static_cast<std::size_t>(i)].point.allFinite() &&
           std::isfinite(m.points[static_cast<std::size_t>(i)].separation);
    }
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "case " << k << ": manifold " << m.count << " normal "
                    << m.normal.transpose();
    }
  }
}

}  // namespace
}  // namespace cardemo::stress
