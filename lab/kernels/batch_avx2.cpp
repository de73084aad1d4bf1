// The batch kernels four pairs at a time with AVX2 (+ FMA for the explicit fma of the 3D edge
// axes). Built with -mavx2 -mfma (lab/CMakeLists.txt) and called only after batchPathAvailable says
// the CPU has both, so the default build still runs on any x86-64.
//
// Includes nothing but the intrinsics and the kernel header (no Eigen, no <cmath>): an inline
// function instantiated here with AVX2 encodings could otherwise be picked by the linker for the
// whole program.

#if defined(CARDEMO_BATCH_AVX2)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "batch_avx2.cpp needs -mavx2 -mfma (set in lab/CMakeLists.txt)"
#endif

#include <immintrin.h>

#include "lab/kernels/batch_kernels.hpp"
#include "lab/kernels/lanes_avx2.hpp"
#include "lab/kernels/manifold2_lanes.hpp"

namespace cardemo::batch_detail {

void overlap2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit) {
  runOverlap2<Lane4>(a, b, first, last, hit);
}

void collide2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  const Sat2Out& out) {
  runCollide2<Lane4>(a, b, first, last, out);
}

void manifold2Avx2(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                   std::size_t first, std::size_t last, const Manifold2Out& out) {
  runManifold2<Lane4>(a, b, settings, first, last, out);
}

void overlap3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit) {
  runOverlap3<Lane4>(a, b, first, last, hit);
}

void separation3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                     double* separation) {
  runSeparation3<Lane4>(a, b, first, last, separation);
}

}  // namespace cardemo::batch_detail

#endif
