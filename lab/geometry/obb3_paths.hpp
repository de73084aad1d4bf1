#pragma once
/// src/geometry/obb3's one-pair queries on the widest batch path the CPU has: the common case in
/// one AVX2 (or AVX-512VL) register per 3-vector, bit for bit what src's portable code gives.

#include "geometry/obb3.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// collideObb3 with its common case (every edge gap clear of the A-frame filter) in the vector
/// kernel of geometry/batch_path's path; the same bits as collideObb3 on every path.
[[nodiscard]] SatResult3 collideObb3OnPath(const Obb3& a, const Obb3& b);

/// overlapObb3 with its common case in the vector kernel of the batch path; the same verdicts.
[[nodiscard]] bool overlapObb3OnPath(const Obb3& a, const Obb3& b);

}  // namespace cardemo
