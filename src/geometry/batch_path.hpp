#pragma once
/// Which implementation the batch kernels (obb2_batch, obb3_batch) run: chosen once at run time.

#include <atomic>

namespace cardemo {

/// An implementation of the batch kernels. All give the same results (the 2D ones bit for bit
/// equal to the scalar functions); they differ only in speed.
enum class BatchPath {
  kPortable,  ///< One pair at a time, plain C++: runs on any CPU.
  kAvx2,      ///< Four pairs at a time with AVX2 and FMA (x86-64 CPUs that have both).
  kAvx512,    ///< AVX-512F for the 2D and 3D kernels (eight doubles, sixteen floats); needs VL too.
};

/// True when `path` was built, the CPU can run it and CARDEMO_BATCH_PATH names no narrower path
/// (`avx2` makes a CPU with AVX-512 behave as one without it; `portable` as one without either).
[[nodiscard]] bool batchPathAvailable(BatchPath path);

namespace batch_path_detail {
/// The path in use as an int, or kUnchosen before the first batchPath() or setBatchPath().
/// Constant-initialised, so it is valid before any dynamic initialiser runs.
extern std::atomic<int> chosen;
/// The value of `chosen` before a path is chosen.
inline constexpr int kUnchosen = -1;
/// Chooses the path from CARDEMO_BATCH_PATH on the first batchPath().
BatchPath chooseFromEnvironment();
}  // namespace batch_path_detail

/// The path in use: the widest available (see batchPathAvailable for CARDEMO_BATCH_PATH), unless
/// setBatchPath chose another.
// Inline, so that a dispatching caller in any file pays one load and one compare (the grid's
// query is inlined into the game's step and checks it on every call).
[[nodiscard]] inline BatchPath batchPath() {
  const int path = batch_path_detail::chosen.load(std::memory_order_relaxed);
  if (path != batch_path_detail::kUnchosen) [[likely]]
    return static_cast<BatchPath>(path);
  return batch_path_detail::chooseFromEnvironment();
}

/// The path that CARDEMO_BATCH_PATH=`name` selects: the widest available one at or below the
/// named path; the widest available one when `name` is null or names no path.
[[nodiscard]] BatchPath batchPathNamed(const char* name);

/// Forces a path (tests and benchmarks run each). `path` must be available.
void setBatchPath(BatchPath path);

/// "portable", "avx2" or "avx512".
[[nodiscard]] const char* batchPathName(BatchPath path);

}  // namespace cardemo
