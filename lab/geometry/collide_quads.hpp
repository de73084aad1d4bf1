#pragma once
/// The SAT of two quadrilaterals (boxes as polygons, the commonest polygon pair) without copying
/// either into sat_polygon.cpp's shapes, four axes a step where the CPU has AVX2: bit for bit what
/// src's collidePolygons gives.

#include "geometry/convex_polygon.hpp"
#include "geometry/polygon_view.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// collidePolygons(a, b), with a pair of quadrilaterals on the widest batch path the CPU has
/// (geometry/batch_path); any other pair, or one outside the fast range, goes to collidePolygons.
[[nodiscard]] SatResult2 collideQuads(PolygonView a, PolygonView b);

}  // namespace cardemo
