#pragma once
/// Test helpers for code with several dispatch paths (geometry/batch_path): the paths to run, and
/// a guard that restores the process-wide choice.

#include <cstdint>
#include <vector>

#include "geometry/batch_path.hpp"
#include "geometry/bit_cast.hpp"

namespace cardemo::testing {

/// True when x and y are the same double bit for bit (so -0 differs from +0, and NaN can match).
inline bool sameBits(double x, double y) {
  return bitCast<std::uint64_t>(x) == bitCast<std::uint64_t>(y);
}

/// Every path this build and CPU can run: the portable one always, the wider ones where the CPU
/// has them (a path a kernel family lacks runs that family's next narrower one).
inline std::vector<BatchPath> availableBatchPaths() {
  std::vector<BatchPath> paths{BatchPath::kPortable};
  for (const BatchPath path : {BatchPath::kAvx2, BatchPath::kAvx512}) {
    if (batchPathAvailable(path)) paths.push_back(path);
  }
  return paths;
}

/// Restores the process-wide batch path when it goes out of scope.
class BatchPathGuard {
 public:
  BatchPathGuard() : saved_(batchPath()) {}
  ~BatchPathGuard() { setBatchPath(saved_); }
  BatchPathGuard(const BatchPathGuard&) = delete;
  BatchPathGuard& operator=(const BatchPathGuard&) = delete;

 private:
  BatchPath saved_;
};

}  // namespace cardemo::testing
