#pragma once
/// The static colliders of a world: parked cars' boxes and convex obstacles, stored apart.

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collision/narrow_phase.hpp"
#include "geometry/aabb.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"

namespace cardemo {

/// Every static collider under one index: the boxes first (0 <= i < boxCount()), then the
/// polygons (boxCount() <= i < size()). Boxes are kept in their own array of Obb2 (48 bytes each)
/// rather than as StaticShape variants sized for a 16-vertex polygon, so the narrow phase reads
/// only the bytes of the shape it tests. Immutable once built.
class StaticColliders {
 public:
  /// No colliders.
  StaticColliders() = default;
  /// Takes the boxes (indices 0..) and then the polygons (indices after the boxes), in order, and
  /// computes the tight bounds of each.
  StaticColliders(std::vector<Obb2> boxes, std::vector<ConvexPolygon> polygons);

  /// Number of colliders, boxes and polygons.
  [[nodiscard]] std::size_t size() const { return bounds_.size(); }
  /// Number of boxes: the indices below it are boxes, the rest polygons.
  [[nodiscard]] std::uint32_t boxCount() const { return box_count_; }
  /// True when collider i is a box (i < size()).
  [[nodiscard]] bool isBox(std::uint32_t i) const { return i < box_count_; }
  /// Collider i as a box (requires isBox(i)).
  [[nodiscard]] const Obb2& box(std::uint32_t i) const {
    assert(isBox(i));
    return boxes_[i];
  }
  /// Collider i as a polygon (requires !isBox(i) and i < size()).
  [[nodiscard]] const ConvexPolygon& polygon(std::uint32_t i) const {
    assert(!isBox(i) && i < size());
    return polygons_[i - box_count_];
  }
  /// Calls `f` with collider i as `const Obb2&` or `const ConvexPolygon&` and returns its result
  /// (both calls must return the same type; i < size()).
  template <class F>
  decltype(auto) visit(std::uint32_t i, F&& f) const {
    if (isBox(i)) return std::forward<F>(f)(box(i));
    return std::forward<F>(f)(polygon(i));
  }
  /// A copy of collider i as a variant (for code off the hot path: drawing, comparisons).
  [[nodiscard]] StaticShape shape(std::uint32_t i) const;
  /// Tight bounds of collider i.
  [[nodiscard]] const Aabb2& bounds(std::uint32_t i) const { return bounds_[i]; }
  /// Tight bounds of every collider, by index (what the broad phase is built over).
  [[nodiscard]] std::span<const Aabb2> bounds() const { return bounds_; }

 private:
  std::vector<Obb2> boxes_;
  std::vector<ConvexPolygon> polygons_;
  std::vector<Aabb2> bounds_;  // boxes' then polygons', by collider index
  std::uint32_t box_count_ = 0;
};

}  // namespace cardemo
