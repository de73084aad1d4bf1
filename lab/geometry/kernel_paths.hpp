#pragma once
/// Which batch paths the lab has kernels of its own for.

#include "geometry/batch_path.hpp"

namespace cardemo {

/// True when the lab was built with kernels for `path` (the AVX-512 ones only with
/// CARDEMO_BATCH_AVX512, lab/CMakeLists.txt): on an available path without them the lab runs the
/// next narrower path's kernels. Benchmarks name a path only where this and batchPathAvailable
/// both hold.
[[nodiscard]] bool kernelsBuiltFor(BatchPath path);

}  // namespace cardemo
