// The grid scan four boxes at a time with AVX2. Built with -mavx2 (CMakeLists.txt) and called only
// after geometry/batch_path says the CPU has it.
//
// Includes nothing but the intrinsics and the scan headers, for the reason given in
// kernels/batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__)
#error "grid_scan_avx2.cpp needs -mavx2 (set in CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "collision/grid_rows.hpp"
#include "collision/grid_scan.hpp"

namespace cardemo::grid_detail {
namespace {

// For a mask m of found lanes: the byte shuffle that moves their 32-bit ids to the front, and how
// many there are.
struct Compress {
  alignas(16) std::uint8_t shuffle[16][16];
  std::uint8_t count[16];
  constexpr Compress() : shuffle{}, count{} {
    for (unsigned m = 0; m < 16; ++m) {
      unsigned n = 0;
      for (unsigned lane = 0; lane < 4; ++lane) {
        if (((m >> lane) & 1u) == 0) continue;
        for (unsigned byte = 0; byte < 4; ++byte) {
          shuffle[m][4 * n + byte] = static_cast<std::uint8_t>(4 * lane + byte);
        }
        ++n;
      }
      count[m] = static_cast<std::uint8_t>(n);
    }
  }
};
constexpr Compress kCompress;

// Lanes [0, n) of a step, for the n boxes left in a row (4 or more: all).
constexpr std::uint8_t kLive[5] = {0x0, 0x1, 0x3, 0x7, 0xF};

}  // namespace

void scanLevelsAvx2(const LevelArrays* levels, std::size_t level_count, const QueryBox& q,
                    IdSink& sink) {
  const __m256d qmin_x = _mm256_set1_pd(q.min[0]), qmin_y = _mm256_set1_pd(q.min[1]);
  const __m256d qmax_x = _mm256_set1_pd(q.max[0]), qmax_y = _mm256_set1_pd(q.max[1]);
  const auto step4 = [&](const Boxes& a, std::uint32_t k, std::uint32_t end, std::uint32_t* buffer,
                         std::size_t count) {
    // Closed intervals: touching counts. Ordered comparisons, so a NaN box is never found.
    __m256d in = _mm256_and_pd(_mm256_cmp_pd(_mm256_loadu_pd(a.min_x + k), qmax_x, _CMP_LE_OQ),
                               _mm256_cmp_pd(qmin_x, _mm256_loadu_pd(a.max_x + k), _CMP_LE_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(_mm256_loadu_pd(a.min_y + k), qmax_y, _CMP_LE_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(qmin_y, _mm256_loadu_pd(a.max_y + k), _CMP_LE_OQ));
    const std::uint32_t left = end - k;
    const unsigned bits =
        static_cast<unsigned>(_mm256_movemask_pd(in)) & kLive[left < 4 ? left : 4];
    // All four ids are stored, the found ones first; the count advances past those only.
    const __m128i ids = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a.ids + k));
    const __m128i order = _mm_load_si128(reinterpret_cast<const __m128i*>(kCompress.shuffle[bits]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(buffer + count), _mm_shuffle_epi8(ids, order));
    return count + kCompress.count[bits];
  };
  scanLevels<4>(levels, level_count, q, sink, step4);
}

}  // namespace cardemo::grid_detail

#endif
