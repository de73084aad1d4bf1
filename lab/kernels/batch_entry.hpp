#pragma once
/// Internal to the batch kernels: plain views of the struct-of-arrays data and the entry points
/// of each implementation. Deliberately free of Eigen and the standard library's inline code, so
/// the AVX2 translation unit instantiates nothing that the linker could share with the rest.

#include <cstddef>
#include <cstdint>

namespace cardemo::batch_detail {

/// One 2D box, unpacked: the query (A) of a batch.
struct Box2One {
  double cx, cy;  ///< Centre, world metres.
  double ux, uy;  ///< Unit local +x axis, world frame.
  double hx, hy;  ///< Half extents, metres.
};

/// Many 2D boxes (B), one array per field, indexed alike.
struct Box2Arrays {
  const double *cx, *cy;  ///< Centres, world metres.
  const double *ux, *uy;  ///< Unit local +x axes, world frame.
  const double *hx, *hy;  ///< Half extents, metres.
};

/// Where collide2 writes: separation and unit normal (A towards B), one entry per box.
struct Sat2Out {
  double* separation;  ///< Metres, <= 0 when touching or overlapping.
  double *nx, *ny;     ///< Normal components, world frame.
};

/// Where manifold2 writes, one entry per pair (manifold2_batch.hpp, Manifold2Batch): the normal,
/// the points' positions, separations and features (entries past the count unspecified), the
/// count and the reference face.
struct Manifold2Out {
  double *nx, *ny;                    ///< Unit normal from A towards B.
  double *p0x, *p0y, *p1x, *p1y;      ///< Points on B's surface, world metres.
  double *separation0, *separation1;  ///< Their separations, metres.
  std::int32_t *feature0, *feature1;  ///< Their feature ids.
  std::int32_t* count;                ///< 0, 1 or 2.
  std::int32_t* reference_face;       ///< 0-7, or -1 for none.
};

/// ManifoldSettings as the manifold kernel reads them: margin(x) = relative |x| + absolute.
struct ManifoldParams {
  double max_separation;  ///< Points farther apart are not contacts, metres.
  double relative;        ///< 1 - ManifoldSettings::relative_tolerance.
  double absolute;        ///< ManifoldSettings::absolute_tolerance, metres.
};

/// The float copy of one 2D box (A) that the float pre-filter reads: centre relative to the
/// batch's reference point (the difference taken in double, then rounded), axis and half extents
/// rounded to float, and the per-call part of the error bound (batch2_filter.hpp).
struct Box2FilterOne {
  float x, y;    ///< Centre minus the batch's reference point, metres.
  float ux, uy;  ///< Unit local +x axis, world frame.
  float hx, hy;  ///< Half extents, metres.
  float bound;   ///< A's share of the decision margin, metres (rounded up).
};

/// The float copy of many 2D boxes (B), one array per field, for the float pre-filter.
struct Box2FilterArrays {
  const float *x, *y;    ///< Centres minus the batch's reference point, metres.
  const float *ux, *uy;  ///< Unit local +x axes, world frame.
  const float *hx, *hy;  ///< Half extents, metres.
  const float* bound;    ///< Each box's share of the decision margin, metres (rounded up).
};

/// One 3D box, unpacked: the query (A). r[3*j + k] is component k of box axis j (column j).
struct Box3One {
  double cx, cy, cz;  ///< Centre, metres.
  double r[9];        ///< Rotation columns, column-major.
  double hx, hy, hz;  ///< Half extents, metres.
  /// Bound on the error of an A-frame edge gap (gap times axis length) per metre of the pair's
  /// scale, for this A against the batch's boxes (+infinity: every lane takes the accurate path).
  double edge_gap_error;
  /// Squared A-frame edge-axis length above which that axis's normalised gap is within
  /// kSeparationTolerance (batch_kernels.hpp) times the pair's scale.
  double min_edge_length2;
};

/// Many 3D boxes (B), one array per field; r[3*j + k] holds component k of column j.
struct Box3Arrays {
  const double *cx, *cy, *cz;  ///< Centres, metres.
  const double* r[9];          ///< Rotation columns, column-major.
  const double *hx, *hy, *hz;  ///< Half extents, metres.
};

/// The float copy of one 3D box (A) that the 3D float pre-filter reads (batch3_filter.hpp): centre
/// relative to the batch's reference point (the difference taken in double, then rounded),
/// rotation and half extents rounded to float, and A's share of the decision margin.
struct Box3FilterOne {
  float c[3];   ///< Centre minus the batch's reference point, metres.
  float r[9];   ///< Rotation columns, column-major: r[3*j + k] is component k of axis j.
  float h[3];   ///< Half extents, metres.
  float bound;  ///< A's share of the decision margin, metres (rounded up).
};

/// The float copy of many 3D boxes (B), one array per field, for the 3D float pre-filter.
struct Box3FilterArrays {
  const float* c[3];   ///< Centres minus the batch's reference point, metres.
  const float* r[9];   ///< Rotation columns, column-major.
  const float* h[3];   ///< Half extents, metres.
  const float* bound;  ///< Each box's share of the decision margin, metres (rounded up).
};

// Each function handles boxes [first, last) of `b` and writes entry i of the output for box i.
void overlap2Portable(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                      std::uint8_t* hit);
void collide2Portable(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                      const Sat2Out& out);
void overlap3Portable(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                      std::uint8_t* hit);
void separation3Portable(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                         double* separation);

void overlap2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit);
// The manifolds of pairs (a[i], b[i]) for i in [first, last), where last - first is a multiple of
// four: manifoldObb2 with no previous face, bit for bit (manifold2_lanes.hpp).
void manifold2Avx2(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                   std::size_t first, std::size_t last, const Manifold2Out& out);
void collide2Avx2(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                  const Sat2Out& out);
// 2D with the float pre-filter (batch2_filter.hpp): same verdicts as overlap2*, bit for bit.
// Returns how many boxes the filter left undecided and sent to the double kernel.
std::size_t overlap2FilteredAvx2(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                 const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                 std::uint8_t* hit);
// The same with sixteen floats per instruction, the undecided boxes gathered eight at a time
// into a lane group of the double kernel (batch_avx512.cpp, filter_run_avx512.hpp).
std::size_t overlap2FilteredAvx512(const Box2One& a, const Box2Arrays& b, const Box2FilterOne& fa,
                                   const Box2FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit);
// On AVX-512F, eight doubles per lane group (batch_avx512.cpp).
void overlap2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit);
void collide2Avx512(const Box2One& a, const Box2Arrays& b, std::size_t first, std::size_t last,
                    const Sat2Out& out);
void overlap3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                    std::uint8_t* hit);
void separation3Avx512(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                       double* separation);
// manifold2Avx2 eight pairs at a time: last - first is a multiple of eight.
void manifold2Avx512(const Box2Arrays& a, const Box2Arrays& b, const ManifoldParams& settings,
                     std::size_t first, std::size_t last, const Manifold2Out& out);
// 3D with the float pre-filter (batch3_filter.hpp), eight pairs per instruction; the boxes it
// leaves undecided go, copied four at a time into a lane group, to overlap3Avx2. Same verdicts as
// overlap3*, bit for bit. Returns how many boxes the filter left undecided.
std::size_t overlap3FilteredAvx2(const Box3One& a, const Box3Arrays& b, const Box3FilterOne& fa,
                                 const Box3FilterArrays& fb, std::size_t first, std::size_t last,
                                 std::uint8_t* hit);
void overlap3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                  std::uint8_t* hit);
// The same with sixteen floats per instruction, the undecided boxes copied eight at a time into a
// lane group for overlap3Avx512 (batch_avx512.cpp).
std::size_t overlap3FilteredAvx512(const Box3One& a, const Box3Arrays& b, const Box3FilterOne& fa,
                                   const Box3FilterArrays& fb, std::size_t first, std::size_t last,
                                   std::uint8_t* hit);
void separation3Avx2(const Box3One& a, const Box3Arrays& b, std::size_t first, std::size_t last,
                     double* separation);

}  // namespace cardemo::batch_detail
