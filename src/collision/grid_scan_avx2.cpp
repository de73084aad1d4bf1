// The grid scan four boxes at a time with AVX2. Built with -mavx2 (CMakeLists.txt) and called only
// after geometry/batch_path says the CPU has it.
//
// Includes nothing but the intrinsics and the scan headers, for the reason given in
// lab/kernels/batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__)
#error "grid_scan_avx2.cpp needs -mavx2 (set in CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "collision/grid_rows.hpp"
#include "collision/grid_scan.hpp"

namespace cardemo::grid_detail {
namespace {

// The lanes set in a 4-bit mask m of found lanes, in order.
struct FoundLanes {
  unsigned lane[4]{};
  unsigned count = 0;
  constexpr explicit FoundLanes(unsigned m) {
    for (unsigned l = 0; l < 4; ++l) {
      if (((m >> l) & 1u) != 0) lane[count++] = l;
    }
  }
};

// For a mask m of found lanes: the byte shuffle that moves their 32-bit ids to the front, and how
// many there are.
struct Compress {
  alignas(16) std::uint8_t shuffle[16][16];
  std::uint8_t count[16];
  constexpr Compress() : shuffle{}, count{} {
    for (unsigned m = 0; m < 16; ++m) {
      const FoundLanes found(m);
      for (unsigned n = 0; n < found.count; ++n) {
        for (unsigned byte = 0; byte < 4; ++byte) {
          shuffle[m][4 * n + byte] = static_cast<std::uint8_t>(4 * found.lane[n] + byte);
        }
      }
      count[m] = static_cast<std::uint8_t>(found.count);
    }
  }
};
constexpr Compress kCompress;

// Lanes [0, n) of a step, for the n boxes left in a row (4 or more: all).
constexpr std::uint8_t kLive[5] = {0x0, 0x1, 0x3, 0x7, 0xF};

// The tables of scanFewAvx2's step, together so that one register addresses both. slot[c][m]: for
// the count c of ids found before and a mask m of found lanes, for each of the eight result slots,
// 0x80 | the lane whose id goes there (slots c .. c + found - 1), else 0 (keep the slot).
// Sign-extended to 32 bits this is both the vpermd index (low three bits) and the blend mask.
// advance[m]: the found lanes of m, in steps of slot[c] to slot[c + 1].
struct FewTables {
  std::uint8_t slot[kFewIds + 1][16][8];
  std::uint16_t advance[16];
  constexpr FewTables() : slot{}, advance{} {
    for (unsigned m = 0; m < 16; ++m) {
      const FoundLanes found(m);
      for (unsigned n = 0; n < found.count; ++n) {
        for (unsigned c = 0; c + n < kFewIds; ++c) {
          slot[c][m][c + n] = static_cast<std::uint8_t>(0x80 | found.lane[n]);
        }
      }
      advance[m] = static_cast<std::uint16_t>(found.count * sizeof slot[0]);
    }
  }
};
constexpr FewTables kFew;

// One compare-exchange round of a sorting network: each slot against the slot `partner` puts in
// its place; the slots set in kTakeMax keep the larger value.
template <int kTakeMax>
[[gnu::always_inline]] inline __m256i exchange(__m256i v, __m256i partner) {
  return _mm256_blend_epi32(_mm256_min_epu32(v, partner), _mm256_max_epu32(v, partner), kTakeMax);
}

// Sorts the eight unsigned slots increasing: Batcher's bitonic sorter, each merge comparing a
// block with its mirror image first.
[[gnu::always_inline]] inline __m256i sort8(__m256i v) {
  v = exchange<0xAA>(v, _mm256_shuffle_epi32(v, 0xB1));  // sorted pairs
  v = exchange<0xCC>(v, _mm256_shuffle_epi32(v, 0x1B));  // sorted fours: mirror, then
  v = exchange<0xAA>(v, _mm256_shuffle_epi32(v, 0xB1));  // neighbours
  v = exchange<0xF0>(v, _mm256_shuffle_epi32(_mm256_permute4x64_epi64(v, 0x4E), 0x1B));
  v = exchange<0xCC>(v, _mm256_shuffle_epi32(v, 0x4E));  // sorted eight: mirror, then distance 2,
  v = exchange<0xAA>(v, _mm256_shuffle_epi32(v, 0xB1));  // then neighbours
  return v;
}

// scanFewAvx2's state: the query, and the ids found so far, in scan order, in a register. Each
// step moves its found ids (up to four) into slots count .. count + found - 1 with one permute and
// one blend; `at` is the count in rows of kFew.slot. The slots start as 0xFFFFFFFF (above any id,
// which is below 2^32 - 1), so those past the count sort last as they are.
struct FewIds {
  __m256d qmin_x, qmin_y, qmax_x, qmax_y;
  __m256 found = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
  std::size_t at = 0;

  [[gnu::always_inline]] FewIds(const double* query_min, const double* query_max)
      : qmin_x(_mm256_set1_pd(query_min[0])),
        qmin_y(_mm256_set1_pd(query_min[1])),
        qmax_x(_mm256_set1_pd(query_max[0])),
        qmax_y(_mm256_set1_pd(query_max[1])) {}

  // Rows base .. min(base + 55, w.y1) of level l; false when they hold more ids than are kept.
  [[gnu::always_inline]] bool rows(const LevelArrays& l, const Window& w, std::int64_t base) {
    const double *const min_x = l.min_x, *const min_y = l.min_y;
    const double *const max_x = l.max_x, *const max_y = l.max_y;
    const std::uint32_t* const ids = l.ids;
    const std::int64_t row_stride = l.row_stride;
    // Row base + r holds the boxes [first[r * row_stride], end[r * row_stride]) of the window.
    const std::uint32_t* const first = l.cell_start + base * row_stride + w.x0;
    const std::uint32_t* const end = l.cell_start + base * row_stride + w.x1 + 1;
    // Rows base .. base + 55 from one unaligned load (x86 is little-endian, so bit y of the bit
    // set is bit y % 8 of byte y / 8; the word past the last row's keeps the load inside).
    std::uint64_t occupied;
    __builtin_memcpy(&occupied, reinterpret_cast<const unsigned char*>(l.row_bits) + (base >> 3),
                     sizeof occupied);
    occupied >>= base & 7;
    const std::int64_t last = w.y1 - base;
    occupied &= (std::uint64_t{2} << (last < 55 ? last : 55)) - 1;
    for (; occupied != 0; occupied &= occupied - 1) {
      const std::int64_t row = static_cast<unsigned>(__builtin_ctzll(occupied)) * row_stride;
      // 64-bit, so that indexing by k needs no widening each step.
      std::int64_t k = first[row];
      const std::int64_t stop = end[row];
      // One step whatever the row holds (an empty window's lanes find nothing), as scanLevels.
      do {
        // Closed intervals: touching counts. Ordered comparisons: a NaN box is never found. The
        // query comes first in each, so that every box load folds into its comparison.
        __m256d in = _mm256_and_pd(_mm256_cmp_pd(qmax_x, _mm256_loadu_pd(min_x + k), _CMP_GE_OQ),
                                   _mm256_cmp_pd(qmin_x, _mm256_loadu_pd(max_x + k), _CMP_LE_OQ));
        in = _mm256_and_pd(in, _mm256_cmp_pd(qmax_y, _mm256_loadu_pd(min_y + k), _CMP_GE_OQ));
        in = _mm256_and_pd(in, _mm256_cmp_pd(qmin_y, _mm256_loadu_pd(max_y + k), _CMP_LE_OQ));
        // No mask for the lanes past `stop`: they hold boxes right of the window in this row, or
        // the NaN boxes after it (kRowPadding), and none of them passes.
        const unsigned bits = static_cast<unsigned>(_mm256_movemask_pd(in));
        const __m256i slots = _mm256_cvtepi8_epi32(
            _mm_loadl_epi64(reinterpret_cast<const __m128i*>(&kFew.slot[0][bits][0] + at)));
        const __m256i lanes =
            _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(ids + k)));
        found =
            _mm256_blendv_ps(found, _mm256_castsi256_ps(_mm256_permutevar8x32_epi32(lanes, slots)),
                             _mm256_castsi256_ps(slots));
        at += kFew.advance[bits];
        if (at > kFewIds * sizeof kFew.slot[0]) [[unlikely]]
          return false;
        k += 4;
      } while (k < stop);
    }
    return true;
  }

  // Writes the ids found to few[0, kFewIds) in increasing order and returns how many.
  [[gnu::always_inline]] std::size_t finish(std::uint32_t* few) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(few), sort8(_mm256_castps_si256(found)));
    return at / sizeof kFew.slot[0];
  }
};

// scanFewAvx2 for any number of levels and rows.
[[gnu::noinline]] std::size_t scanFewLevels(const LevelArrays* levels, std::size_t level_count,
                                            const double* query_min, const double* query_max,
                                            std::uint32_t* few) {
  FewIds scan(query_min, query_max);
  for (std::size_t i = 0; i < level_count; ++i) {
    const Window w = windowOf(levels[i], query_min, query_max);
    if (w.x1 < w.x0) continue;  // an inverted query
    for (std::int64_t base = w.y0; base <= w.y1; base += 56) {
      if (!scan.rows(levels[i], w, base)) return kFewIds + 1;
    }
  }
  return scan.finish(few);
}

}  // namespace

void scanLevelsAvx2(const LevelArrays* levels, std::size_t level_count, const QueryBox& q,
                    IdSink& sink) {
  const __m256d qmin_x = _mm256_set1_pd(q.min[0]), qmin_y = _mm256_set1_pd(q.min[1]);
  const __m256d qmax_x = _mm256_set1_pd(q.max[0]), qmax_y = _mm256_set1_pd(q.max[1]);
  const auto step4 = [&](const Boxes& a, std::uint32_t k, std::uint32_t end, std::uint32_t* buffer,
                         std::size_t count) {
    // Closed intervals: touching counts. Ordered comparisons, so a NaN box is never found. The
    // query comes first in each, so that every box load folds into its comparison.
    __m256d in = _mm256_and_pd(_mm256_cmp_pd(qmax_x, _mm256_loadu_pd(a.min_x + k), _CMP_GE_OQ),
                               _mm256_cmp_pd(qmin_x, _mm256_loadu_pd(a.max_x + k), _CMP_LE_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(qmax_y, _mm256_loadu_pd(a.min_y + k), _CMP_GE_OQ));
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

std::size_t scanFewAvx2(const LevelArrays* levels, std::size_t level_count, const double* query_min,
                        const double* query_max, std::uint32_t* few) {
  // No test against a level's bounds: off them the window is clamped to the edge cells, whose
  // boxes the query does not touch (and a NaN query touches nothing). The common query (one
  // level, one word of rows) runs here; any other in a function of its own, so that this one
  // keeps fewer values live (and saves fewer registers).
  if (level_count == 1) [[likely]] {
    const Window w = windowOf(levels[0], query_min, query_max);
    if (w.x0 <= w.x1 && w.y1 - w.y0 < 56) [[likely]] {
      FewIds scan(query_min, query_max);
      if (!scan.rows(levels[0], w, w.y0)) return kFewIds + 1;  // more than kept
      return scan.finish(few);
    }
  }
  return scanFewLevels(levels, level_count, query_min, query_max, few);
}

}  // namespace cardemo::grid_detail

#endif
