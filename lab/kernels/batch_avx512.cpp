// The batch kernels with AVX-512F: the 2D boolean SAT through the float pre-filter, sixteen pairs
// per instruction, and every double kernel eight pairs per instruction (the 2D SAT with separation
// and normal, the 2D boolean SAT for the boxes the filter leaves undecided, the 2D contact
// manifold, and both 3D kernels with their A-frame filter). Built with -mavx512f
// (lab/CMakeLists.txt) and called only after batchPathAvailable says the CPU has it.
//
// Includes nothing but the intrinsics and the kernel headers, for the reason given in
// batch_avx2.cpp.

#if defined(CARDEMO_BATCH_AVX512)
#if !defined(__AVX512F__)
#error "batch_avx512.cpp needs -mavx512f (set in lab/CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "lab/kernels/batch2_filter.hpp"
#include "lab/kernels/batch3_filter.hpp"
#include "lab/kernels/batch_kernels.hpp"
#include "lab/kernels/box_fields.hpp"
#include "lab/kernels/filter_run_avx512.hpp"
#include "lab/kernels/lanes_avx512.hpp"
#include "lab/kernels/manifold2_lanes.hpp"

namespace cardemo::batch_detail {

// The 2D boolean kernel prefetches the double fields of the boxes its filter leaves open when
// they take more bytes than this. Measured on the benchmark's boxes: at 64k boxes (3 MiB) the
// prefetches cost more than they saved, at 1M (48 MiB) they saved about 30 % of the time.
constexpr std::size_t kPrefetchAbove = std::size_t{16} << 20;

std::size_t overlap2FilteredAvx512(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                   const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit) {
  const FilterQuery2<Float16> q = splatQuery<Float16>(fa);
  const Box2FilterArrays filter_arrays = fb;
  const Box2Fields source = fieldsOf(b);
  return runFilteredGathered(
      first, last, hit,
      [q, filter_arrays](std::size_t i) { return filter2<Float16>(q, filter_arrays, i); },
      source.field,
      [&a](const double(&f)[6][8], std::uint8_t* group_hit) {
        storeHits(group_hit, separated2<Double8>(a, arraysOf(f), 0));
      },
      [&source, prefetch = (last - first) * sizeof(double) * 6 > kPrefetchAbove](std::size_t i) {
        // The group's double fields, which the gathers read when the buffer of open boxes is
        // next decided: in a batch larger than the caches those sparse reads would miss. In a
        // smaller one the prefetches cost more than they save.
        if (!prefetch) return;
        for (std::size_t f = 0; f < 6; ++f) {
          __builtin_prefetch(source.field[f] + i);
          __builtin_prefetch(source.field[f] + i + 8);
        }
      });
}

std::size_t overlap3FilteredAvx512(const Box3One& a, const Box3Arrays& b, const Box3FilterOne& fa,
                                   const Box3FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit) {
  // The open boxes are copied lane by lane, not gathered as in the 2D kernel above: with fifteen
  // fields the gathers were slower at 1M boxes (lab/README.md, "Ideas measured and not kept").
  return runFilteredOverlap3<Float16>(
      fa, fb, first, last, hit, [&](const std::size_t* boxes, std::size_t count) {
        decideOpenBoxes<8>(fieldsOf(b).field, boxes, count, hit,
                           [&](const double(&f)[15][8], std::uint8_t* group_hit) {
                             runOverlap3<Double8>(a, arraysOf(f), 0, 8, group_hit);
                           });
      });
}

void overlap2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit) {
  runOverlap2<Double8>(a, b, first, last, hit);
}

void collide2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    const Sat2Out& out) {
  runCollide2<Double8>(a, b, first, last, out);
}

void manifold2Avx512(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                     std::size_t first, std::size_t last, const Manifold2Out& out) {
  runManifold2<Double8>(a, b, settings, first, last, out);
}

void overlap3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit) {
  runOverlap3<Double8>(a, b, first, last, hit);
}

void separation3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                       double* separation) {
  runSeparation3<Double8>(a, b, first, last, separation);
}

}  // namespace cardemo::batch_detail

#endif
