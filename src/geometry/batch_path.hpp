#pragma once
/// Which implementation the batch kernels (obb2_batch, obb3_batch) run: chosen once at run time.

namespace cardemo {

/// An implementation of the batch kernels. Both give bit-identical results (same operations in
/// the same order, no FMA contraction); they differ only in speed.
enum class BatchPath {
  kPortable,  ///< One pair at a time, plain C++: runs on any CPU.
  kAvx2,      ///< Four pairs at a time with AVX2 and FMA (x86-64 CPUs that have both).
};

/// True when `path` was built and the CPU can run it.
[[nodiscard]] bool batchPathAvailable(BatchPath path);

/// The path in use: AVX2 when available, unless the environment variable CARDEMO_BATCH_PATH is
/// `portable` at the first call, or setBatchPath chose otherwise.
[[nodiscard]] BatchPath batchPath();

/// Forces a path (tests and benchmarks run both). `path` must be available.
void setBatchPath(BatchPath path);

/// "portable" or "avx2".
[[nodiscard]] const char* batchPathName(BatchPath path);

}  // namespace cardemo
