#pragma once
/// Internal to the batch kernels: the loops that run the float pre-filters of the 2D and 3D boolean
/// SATs (batch2_filter.hpp, batch3_filter.hpp). They write every verdict the filter decides and
/// hand the undecided boxes to the double kernel: the whole lane group for the cheap 2D kernel on
/// eight lanes, the undecided boxes alone for the costly 3D one. (The 2D kernel on sixteen lanes,
/// where most groups hold an open lane, gathers them: filter_run_avx512.hpp.)
//
// Included by the filter headers and batch_kernels.hpp only; everything here has internal linkage.

#include <cstddef>
#include <cstdint>

namespace cardemo::batch_detail {
namespace {

// Lane bits of a filter's verdict on one lane group.
struct FilterVerdict {
  unsigned separated;  // decided: separated on some axis
  unsigned decided;    // separated or overlapping for certain
};

// kHitBytes[m] holds eight hit bytes, byte k = 1 - bit k of m: one load per lane mask.
struct HitByteTable {
  std::uint64_t bytes[256];
  constexpr HitByteTable() : bytes{} {
    for (unsigned m = 0; m < 256; ++m) {
      for (unsigned k = 0; k < 8; ++k) {
        if (((m >> k) & 1u) == 0) bytes[m] |= std::uint64_t{1} << (8 * k);
      }
    }
  }
};
inline constexpr HitByteTable kHitBytes;

// Eight hit bytes, hit[k] = 1 - bit k of `separated`.
[[gnu::always_inline]] inline std::uint64_t hitBytes(unsigned separated) {
  return kHitBytes.bytes[separated & 0xFFu];
}

// Writes the hit bytes of the `lanes` live boxes of the lane group at box i (a whole group with
// one table load per eight lanes, the tail lane by lane) and returns the mask of its undecided
// lanes.
template <std::size_t kWidth>
[[gnu::always_inline]] inline unsigned writeVerdicts(const FilterVerdict& v, std::uint8_t* hit,
                                                     std::size_t i, std::size_t lanes) {
  if (lanes == kWidth) [[likely]] {
    for (std::size_t k = 0; k < kWidth; k += 8) {
      const std::uint64_t bytes = hitBytes(v.separated >> k);
      __builtin_memcpy(hit + i + k, &bytes, 8);
    }
  } else {
    for (std::size_t k = 0; k < lanes; ++k) hit[i + k] = ((v.separated >> k) & 1u) != 0 ? 0 : 1;
  }
  return ~v.decided & ((1u << lanes) - 1u);
}

// Runs `filter(i)` (the verdicts of the lane group starting at box i; the float arrays hold whole
// lane groups, padded, so the tail is a whole group computed on the padding) over [first, last),
// writes every decided verdict and calls `exact(i0, i1)` (the double kernel, which rewrites
// hit[i0, i1)) for each lane group with an undecided lane. Returns the number of undecided boxes.
template <std::size_t kWidth, class Filter, class Exact>
std::size_t runFiltered(std::size_t first, std::size_t last, std::uint8_t* hit,
                        const Filter& filter, const Exact& exact) {
  std::size_t undecided = 0;
  const auto group = [&](std::size_t i, std::size_t lanes) {
    const unsigned open = writeVerdicts<kWidth>(filter(i), hit, i, lanes);
    if (open != 0) [[unlikely]] {
      exact(i, i + lanes);
      undecided += static_cast<std::size_t>(__builtin_popcount(open));
    }
  };
  // Whole groups with the lane count fixed, so that the loop carries no tail test.
  std::size_t i = first;
  for (; i + kWidth <= last; i += kWidth) group(i, kWidth);
  if (i < last) group(i, last - i);
  return undecided;
}

// As runFiltered, but the undecided boxes go on one by one: their indices are gathered, and
// `exact_boxes(indices, count)` (the double kernel on those boxes alone, writing hit[indices[k]])
// runs once a buffer of them has filled, and at the end. `on_open(i)` is called for each lane
// group at box i with an open lane, before its boxes join the buffer (to prefetch what
// exact_boxes will read). For a double kernel too costly to run on a whole lane group for one
// undecided lane.
template <std::size_t kWidth, class Filter, class ExactBoxes, class OnOpen>
std::size_t runFilteredByBox(std::size_t first, std::size_t last, std::uint8_t* hit,
                             const Filter& filter, const ExactBoxes& exact_boxes,
                             const OnOpen& on_open) {
  constexpr std::size_t kPending = 64;
  std::size_t pending[kPending + kWidth];
  std::size_t count = 0, undecided = 0;
  for (std::size_t i = first; i < last; i += kWidth) {
    const std::size_t lanes = last - i < kWidth ? last - i : kWidth;
    unsigned open = writeVerdicts<kWidth>(filter(i), hit, i, lanes);
    if (open == 0) [[likely]]
      continue;
    undecided += static_cast<std::size_t>(__builtin_popcount(open));
    on_open(i);
    for (; open != 0; open &= open - 1) {
      pending[count++] = i + static_cast<std::size_t>(__builtin_ctz(open));
    }
    if (count >= kPending) {
      exact_boxes(pending, count);
      count = 0;
    }
  }
  if (count > 0) exact_boxes(pending, count);
  return undecided;
}

// Decides the open boxes boxes[0, count) kLanes at a time: copies field f of each from source[f]
// into one lane group (the last box repeated to fill it), calls `decide(fields, group_out)` (the
// double kernel on that group, writing lane l's result to group_out[l]: a hit byte, or a
// separation) and writes the results of the live lanes to out[box]. The exact_boxes of
// runFilteredByBox, less the kernel; the 3D separation kernel's filter uses it too.
template <std::size_t kLanes, std::size_t kFields, class T, class Decide>
void decideOpenBoxes(const double* const (&source)[kFields], const std::size_t* boxes,
                     std::size_t count, T* out, const Decide& decide) {
  alignas(64) double fields[kFields][kLanes];
  for (std::size_t k = 0; k < count; k += kLanes) {
    const std::size_t lanes = count - k < kLanes ? count - k : kLanes;
    for (std::size_t f = 0; f < kFields; ++f) {
      for (std::size_t l = 0; l < kLanes; ++l) {
        fields[f][l] = source[f][boxes[k + (l < lanes ? l : lanes - 1)]];
      }
    }
    alignas(64) T group_out[kLanes];
    decide(fields, group_out);
    for (std::size_t l = 0; l < lanes; ++l) out[boxes[k + l]] = group_out[l];
  }
}

}  // namespace
}  // namespace cardemo::batch_detail
