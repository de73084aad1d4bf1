#include "collision/static_colliders.hpp"

#include <limits>

namespace cardemo {

StaticColliders::StaticColliders(std::vector<Obb2> boxes, std::vector<ConvexPolygon> polygons)
    : boxes_(std::move(boxes)), polygons_(std::move(polygons)) {
  // Collider indices are 32-bit throughout (grid ids, contacts, hits).
  assert(boxes_.size() + polygons_.size() <= std::numeric_limits<std::uint32_t>::max());
  box_count_ = static_cast<std::uint32_t>(boxes_.size());
  bounds_.reserve(boxes_.size() + polygons_.size());
  for (const Obb2& b : boxes_) bounds_.push_back(boundsOf(b));
  for (const ConvexPolygon& p : polygons_) bounds_.push_back(boundsOf(p));
}

StaticShape StaticColliders::shape(std::uint32_t i) const {
  if (isBox(i)) return box(i);
  return polygon(i);
}

}  // namespace cardemo
