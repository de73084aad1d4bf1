#pragma once
/// Internal to batch_avx512.cpp: runFilteredByBox and decideOpenBoxes (filter_run.hpp) for a
/// sixteen-lane filter, without a branch per open box. A lane group's open boxes join the buffer
/// with one compress and one store, and each field of eight open boxes is read with one gather.
/// The 2D boolean kernel uses it; the 3D one keeps the copies, which were faster with its fifteen
/// fields.
//
// Why: with a tenth of the boxes near touching, five lane groups in six hold an open box, and
// runFilteredByBox's loop over the open lanes (one to four turns, at random) and decideOpenBoxes's
// copies lane by lane (eight scalar stores read back as one vector, which store forwarding cannot
// serve) cost as much as the filter itself.
//
// Included by batch_avx512.cpp only (built with -mavx512f); everything here has internal linkage.

#include <immintrin.h>

#include <cstddef>
#include <cstdint>

#include "lab/kernels/filter_run.hpp"

namespace cardemo::batch_detail {
namespace {

// Boxes per chunk: open boxes are buffered as 32-bit offsets from their chunk's first box. No test
// reaches a second chunk (it would take about 50 GB of boxes); the loop over chunks is kept simple.
inline constexpr std::size_t kGatherChunk = std::size_t{1} << 30;

// Decides the open boxes whose offsets are pending[0, count) (count a multiple of eight, or the
// last call's remainder, padded here): gathers field f of eight of them from source[f] + base
// into one lane group, calls `decide(fields, group_hit)` (the double kernel on that group, one hit
// byte per lane) and writes the live lanes' bytes to hit[base + offset].
template <std::size_t kFields, class Decide>
void decideGathered(const double* const (&source)[kFields], std::size_t base,
                    std::uint32_t* pending, std::size_t count, std::uint8_t* hit,
                    const Decide& decide) {
  alignas(64) double fields[kFields][8];
  alignas(64) std::uint8_t group_hit[8];
  for (std::size_t k = 0; k < count; k += 8) {
    const std::size_t lanes = count - k < 8 ? count - k : 8;
    // The last box fills the lanes past the count (the buffer has room for them).
    for (std::size_t l = lanes; l < 8; ++l) pending[k + l] = pending[k + lanes - 1];
    const __m256i offsets = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pending + k));
    for (std::size_t f = 0; f < kFields; ++f) {
      // The masked form with every lane on: the plain one leaves its source operand undefined,
      // which GCC 12 warns about (GCC bug 105593).
      _mm512_store_pd(fields[f], _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF, offsets,
                                                          source[f] + base, 8));
    }
    decide(fields, group_hit);
    for (std::size_t l = 0; l < lanes; ++l) hit[base + pending[k + l]] = group_hit[l];
  }
}

// runFilteredByBox for a sixteen-lane filter: `filter(i)` gives the verdicts of the lane group at
// box i, every decided one is written to hit, and the open boxes are decided eight at a time by
// decideGathered once a buffer of them has filled, and at the end. `on_open(i)` is called for
// each lane group with an open lane (to prefetch what the gathers will read). Returns the number
// of open boxes.
template <class Filter, std::size_t kFields, class Decide, class OnOpen>
std::size_t runFilteredGathered(std::size_t first, std::size_t last, std::uint8_t* hit,
                                const Filter& filter, const double* const (&source)[kFields],
                                const Decide& decide, const OnOpen& on_open) {
  constexpr std::size_t kPending = 64;
  // Room for a whole group's sixteen offsets past kPending - 1, and for the padding of the last
  // group of eight.
  alignas(64) std::uint32_t pending[kPending + 16 + 8];
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  std::size_t undecided = 0;
  for (std::size_t base = first; base < last; base += kGatherChunk) {
    const std::size_t end = last - base < kGatherChunk ? last : base + kGatherChunk;
    std::size_t count = 0;
    for (std::size_t i = base; i < end; i += 16) {
      const std::size_t lanes = end - i < 16 ? end - i : 16;
      const unsigned open = writeVerdicts<16>(filter(i), hit, i, lanes);
      if (open == 0) continue;
      on_open(i);
      const __m512i offsets = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(i - base)), lane);
      _mm512_storeu_si512(pending + count,
                          _mm512_maskz_compress_epi32(static_cast<__mmask16>(open), offsets));
      const auto opened = static_cast<std::size_t>(__builtin_popcount(open));
      count += opened;
      undecided += opened;
      if (count >= kPending) {
        // Whole groups of eight now; the rest (fewer than eight) moves to the front.
        const std::size_t whole = count & ~std::size_t{7};
        decideGathered(source, base, pending, whole, hit, decide);
        for (std::size_t k = whole; k < count; ++k) pending[k - whole] = pending[k];
        count -= whole;
      }
    }
    if (count > 0) decideGathered(source, base, pending, count, hit, decide);
  }
  return undecided;
}

}  // namespace
}  // namespace cardemo::batch_detail
