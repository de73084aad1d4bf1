#include "geometry/batch_path.hpp"

#include <atomic>
#include <cassert>
#include <cstdlib>
#include <cstring>

namespace cardemo {
namespace {

// The path CARDEMO_BATCH_PATH names, read once: no wider path counts as available, as on a CPU
// without it (so a machine with AVX-512 can run everything as a CPU without it would).
BatchPath ceiling() {
  static const BatchPath named = [] {
    const char* name = std::getenv("CARDEMO_BATCH_PATH");
    if (name != nullptr) {
      for (const BatchPath path : {BatchPath::kPortable, BatchPath::kAvx2}) {
        if (std::strcmp(name, batchPathName(path)) == 0) return path;
      }
    }
    return BatchPath::kAvx512;
  }();
  return named;
}

// True when this build has `path` and the CPU can run it.
bool cpuCanRun(BatchPath path) {
  if (path == BatchPath::kPortable) return true;
#if defined(__x86_64__) || defined(__i386__)
  // The AVX2 kernels also use FMA (the error-free products of the 3D edge axes, the float
  // pre-filter); on the AVX-512 path the grid scan keeps its AVX2 version, so it needs all three,
  // and the lab's one-pair 3D and quadrilateral kernels are built with AVX-512VL too. The path
  // describes the CPU: a lab built without its AVX-512 kernels (lab/CMakeLists.txt) runs their
  // AVX2 versions on it.
  // GCC's check includes the operating system's support for the wider registers (XGETBV).
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#if defined(CARDEMO_BATCH_AVX2)
  if (path == BatchPath::kAvx2) return avx2;
  if (path == BatchPath::kAvx512) {
    return avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  }
#endif
  (void)avx2;
#endif
  return false;
}

// The widest available path at or below `wanted`.
BatchPath widestUpTo(BatchPath wanted) {
  if (wanted == BatchPath::kAvx512 && batchPathAvailable(BatchPath::kAvx512)) {
    return BatchPath::kAvx512;
  }
  if (wanted != BatchPath::kPortable && batchPathAvailable(BatchPath::kAvx2)) {
    return BatchPath::kAvx2;
  }
  return BatchPath::kPortable;
}

}  // namespace

namespace batch_path_detail {

// With a function-local static instead, every dispatching caller also inlined the guard and the
// first call's getenv, and saved registers for them.
constinit std::atomic<int> chosen{kUnchosen};

[[gnu::noinline, gnu::cold]] BatchPath chooseFromEnvironment() {
  int expected = kUnchosen;
  const int named = static_cast<int>(batchPathNamed(std::getenv("CARDEMO_BATCH_PATH")));
  // A setBatchPath that came first wins, as it does over the first read of a static.
  chosen.compare_exchange_strong(expected, named, std::memory_order_relaxed);
  return static_cast<BatchPath>(chosen.load(std::memory_order_relaxed));
}

}  // namespace batch_path_detail

bool batchPathAvailable(BatchPath path) {
  return static_cast<int>(path) <= static_cast<int>(ceiling()) && cpuCanRun(path);
}

BatchPath batchPathNamed(const char* name) {
  if (name != nullptr) {
    for (const BatchPath path : {BatchPath::kPortable, BatchPath::kAvx2, BatchPath::kAvx512}) {
      if (std::strcmp(name, batchPathName(path)) == 0) return widestUpTo(path);
    }
  }
  return widestUpTo(BatchPath::kAvx512);
}

void setBatchPath(BatchPath path) {
  assert(batchPathAvailable(path));
  batch_path_detail::chosen.store(static_cast<int>(path), std::memory_order_relaxed);
}

const char* batchPathName(BatchPath path) {
  switch (path) {
    case BatchPath::kAvx2:
      return "avx2";
    case BatchPath::kAvx512:
      return "avx512";
    case BatchPath::kPortable:
      break;
  }
  return "portable";
}

}  // namespace cardemo
