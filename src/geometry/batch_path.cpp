#include "geometry/batch_path.hpp"

#include <atomic>
#include <cassert>
#include <cstdlib>
#include <cstring>

namespace cardemo {
namespace {

BatchPath initialPath() {
  const char* forced = std::getenv("CARDEMO_BATCH_PATH");
  if (forced != nullptr && std::strcmp(forced, "portable") == 0) return BatchPath::kPortable;
  return batchPathAvailable(BatchPath::kAvx2) ? BatchPath::kAvx2 : BatchPath::kPortable;
}

std::atomic<BatchPath>& chosenPath() {
  static std::atomic<BatchPath> path{initialPath()};
  return path;
}

}  // namespace

bool batchPathAvailable(BatchPath path) {
  if (path == BatchPath::kPortable) return true;
#if defined(CARDEMO_BATCH_AVX2) && (defined(__x86_64__) || defined(__i386__))
  // The AVX2 kernels also use FMA (for the error-free products of the 3D edge axes).
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

BatchPath batchPath() {
  return chosenPath().load(std::memory_order_relaxed);
}

void setBatchPath(BatchPath path) {
  assert(batchPathAvailable(path));
  chosenPath().store(path, std::memory_order_relaxed);
}

const char* batchPathName(BatchPath path) {
  return path == BatchPath::kAvx2 ? "avx2" : "portable";
}

}  // namespace cardemo
