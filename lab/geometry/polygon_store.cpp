#include "lab/geometry/polygon_store.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/convex_polygon.hpp"

namespace cardemo {

std::size_t PolygonStore::add(PolygonView polygon) {
  // The pair queries size their scratch for kMaxVertices.
  if (polygon.count < 3 || polygon.count > ConvexPolygon::kMaxVertices) {
    throw std::invalid_argument("PolygonStore::add: " + std::to_string(polygon.count) +
                                " vertices, not 3 to " +
                                std::to_string(ConvexPolygon::kMaxVertices));
  }
  if (vertices_.size() + static_cast<std::size_t>(polygon.count) >
      std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("PolygonStore::add: more than 2^32 - 1 vertices in all");
  }
  vertices_.insert(vertices_.end(), polygon.vertices, polygon.vertices + polygon.count);
  starts_.push_back(static_cast<std::uint32_t>(vertices_.size()));
  return size() - 1;
}

void PolygonStore::reserve(std::size_t polygons, std::size_t vertices) {
  starts_.reserve(polygons + 1);
  vertices_.reserve(vertices);
}

}  // namespace cardemo
