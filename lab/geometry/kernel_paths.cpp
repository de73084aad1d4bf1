#include "lab/geometry/kernel_paths.hpp"

namespace cardemo {

bool kernelsBuiltFor(BatchPath path) {
  switch (path) {
    case BatchPath::kPortable:
      return true;
    case BatchPath::kAvx2:
#if defined(CARDEMO_BATCH_AVX2)
      return true;
#else
      return false;
#endif
    case BatchPath::kAvx512:
#if defined(CARDEMO_BATCH_AVX2) && defined(CARDEMO_BATCH_AVX512)
      return true;
#else
      return false;
#endif
  }
  return false;
}

}  // namespace cardemo
