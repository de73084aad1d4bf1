#pragma once
/// Internal to the batch kernels: the fields of Box2Arrays and Box3Arrays as lists of pointers, and
/// a lane group's copy of them as arrays again. The padded tails (batch_kernels.hpp) and the boxes
/// the filters leave open (decideOpenBoxes, filter_run.hpp) copy boxes field by field.
//
// Included by the kernel headers only; everything here has internal linkage.

#include <cstddef>

#include "lab/kernels/batch_entry.hpp"

namespace cardemo::batch_detail {
namespace {

// Box2Arrays' six fields in declaration order.
struct Box2Fields {
  const double* field[6];
};

// Box3Arrays' fifteen fields in declaration order (centre, rotation, half extents).
struct Box3Fields {
  const double* field[15];
};

inline Box2Fields fieldsOf(const Box2Arrays& b) {
  return {{b.cx, b.cy, b.ux, b.uy, b.hx, b.hy}};
}

inline Box3Fields fieldsOf(const Box3Arrays& b) {
  return {{b.cx, b.cy, b.cz, b.r[0], b.r[1], b.r[2], b.r[3], b.r[4], b.r[5], b.r[6], b.r[7], b.r[8],
           b.hx, b.hy, b.hz}};
}

// The boxes whose field f is values[f][0, kLanes).
template <std::size_t kLanes>
Box2Arrays arraysOf(const double (&values)[6][kLanes]) {
  return {values[0], values[1], values[2], values[3], values[4], values[5]};
}

template <std::size_t kLanes>
Box3Arrays arraysOf(const double (&values)[15][kLanes]) {
  return {values[0],
          values[1],
          values[2],
          {values[3], values[4], values[5], values[6], values[7], values[8], values[9], values[10],
           values[11]},
          values[12],
          values[13],
          values[14]};
}

}  // namespace
}  // namespace cardemo::batch_detail
