// Box2D 2.4.1 adapter: float world transforms, SetAsBox / Set, b2TestOverlap and b2CollidePolygons.

#include "compare/box2d/box2d_shapes.hpp"

#include <array>
#include <cmath>

namespace cardemo::compare {
namespace {

// What a Box2D user writes: the heading as an angle, handed to b2Rot (sinf/cosf of a float), not
// our exact unit axis. At 90 degrees this gives cos = -4.4e-8 rather than 0, part of the finding.
b2Transform worldTransform(const Obb2& box) {
  const double angle = std::atan2(box.axis.y(), box.axis.x());
  return {b2Vec2(static_cast<float>(box.center.x()), static_cast<float>(box.center.y())),
          b2Rot(static_cast<float>(angle))};
}

}  // namespace

Box2dShape box2dBox(const Obb2& box, float skin) {
  Box2dShape s;
  s.shape.SetAsBox(static_cast<float>(box.half.x()), static_cast<float>(box.half.y()));
  s.shape.m_radius = skin;
  s.xf = worldTransform(box);
  return s;
}

void setBox2dPose(Box2dShape& shape, const Obb2& box) {
  shape.xf = worldTransform(box);
}

Box2dShape box2dPolygon(const ConvexPolygon& polygon, float skin) {
  std::array<b2Vec2, ConvexPolygon::kMaxVertices> points;
  for (int i = 0; i < polygon.count; ++i) {
    const Eigen::Vector2d& v = polygon.vertex(i);
    points[static_cast<std::size_t>(i)] =
        b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
  }
  Box2dShape s;
  s.shape.Set(points.data(), polygon.count);
  s.shape.m_radius = skin;
  s.xf.SetIdentity();
  return s;
}

Box2dVerdict box2dCollide(const Box2dShape& a, const Box2dShape& b) {
  Box2dVerdict v;
  v.overlap = b2TestOverlap(&a.shape, 0, &b.shape, 0, a.xf, b.xf);
  b2Manifold manifold;
  b2CollidePolygons(&manifold, &a.shape, a.xf, &b.shape, b.xf);
  v.points = manifold.pointCount;
  return v;
}

Box2dEdge box2dEdge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, float skin) {
  Box2dEdge e;
  e.shape.SetTwoSided(b2Vec2(static_cast<float>(a.x()), static_cast<float>(a.y())),
                      b2Vec2(static_cast<float>(b.x()), static_cast<float>(b.y())));
  e.shape.m_radius = skin;
  return e;
}

Box2dVerdict box2dCollide(const Box2dShape& polygon, const Box2dEdge& edge) {
  b2Transform identity;
  identity.SetIdentity();
  Box2dVerdict v;
  v.overlap = b2TestOverlap(&edge.shape, 0, &polygon.shape, 0, identity, polygon.xf);
  b2Manifold manifold;
  b2CollideEdgeAndPolygon(&manifold, &edge.shape, identity, &polygon.shape, polygon.xf);
  v.points = manifold.pointCount;
  return v;
}

}  // namespace cardemo::compare
