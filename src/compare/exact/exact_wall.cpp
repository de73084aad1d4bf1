#include <gmpxx.h>

#include "compare/exact/dyadic.hpp"
#include "compare/exact/exact_sat.hpp"

namespace cardemo::exact {

ExactResult collideObbWall(const Obb2& box, const Aabb2& walls, WallSide side) {
  // The box is exactly { centre + a*axis + b*perp : |a| <= hx, |b| <= hy } (obb2.hpp), perp =
  // (-axis.y, axis.x), so its reach from the centre along x is |axis.x| hx + |axis.y| hy and along
  // y |axis.y| hx + |axis.x| hy: its extreme corners, exactly.
  const Dyadic ax = abs(Dyadic(box.axis.x()));
  const Dyadic ay = abs(Dyadic(box.axis.y()));
  const Dyadic hx(box.half.x()), hy(box.half.y());
  const Dyadic reach_x = ax * hx + ay * hy;
  const Dyadic reach_y = ay * hx + ax * hy;
  const Dyadic cx(box.center.x()), cy(box.center.y());
  Dyadic gap;  // from the box to the wall's line: > 0 apart, <= 0 touching or past it
  switch (side) {
    case WallSide::kWest:
      gap = (cx - reach_x) - Dyadic(walls.min.x());
      break;
    case WallSide::kEast:
      gap = Dyadic(walls.max.x()) - (cx + reach_x);
      break;
    case WallSide::kSouth:
      gap = (cy - reach_y) - Dyadic(walls.min.y());
      break;
    case WallSide::kNorth:
      gap = Dyadic(walls.max.y()) - (cy + reach_y);
      break;
  }
  return {gap.sign() <= 0, gap.toFloat(256).get_d()};
}

}  // namespace cardemo::exact
