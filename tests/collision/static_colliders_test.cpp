#include "collision/static_colliders.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <type_traits>
#include <variant>
#include <vector>

#include "geometry/angle.hpp"
#include "geometry/bit_cast.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

// Bit patterns, so that -0.0 differs from 0.0 and "identical" means identical.
std::uint64_t bitsOf(double v) {
  return bitCast<std::uint64_t>(v);
}

bool sameObb(const Obb2& a, const Obb2& b) {
  return bitsOf(a.center.x()) == bitsOf(b.center.x()) &&
         bitsOf(a.center.y()) == bitsOf(b.center.y()) && bitsOf(a.axis.x()) == bitsOf(b.axis.x()) &&
         bitsOf(a.axis.y()) == bitsOf(b.axis.y()) && bitsOf(a.half.x()) == bitsOf(b.half.x()) &&
         bitsOf(a.half.y()) == bitsOf(b.half.y());
}

bool samePolygon(const ConvexPolygon& a, const ConvexPolygon& b) {
  if (a.count != b.count) return false;
  for (int i = 0; i < a.count; ++i) {
    if (bitsOf(a.vertex(i).x()) != bitsOf(b.vertex(i).x()) ||
        bitsOf(a.vertex(i).y()) != bitsOf(b.vertex(i).y())) {
      return false;
    }
  }
  return true;
}

bool sameBounds(const Aabb2& a, const Aabb2& b) {
  return bitsOf(a.min.x()) == bitsOf(b.min.x()) && bitsOf(a.min.y()) == bitsOf(b.min.y()) &&
         bitsOf(a.max.x()) == bitsOf(b.max.x()) && bitsOf(a.max.y()) == bitsOf(b.max.y());
}

ConvexPolygon polygonThrough(const std::vector<Eigen::Vector2d>& points) {
  const std::optional<ConvexPolygon> p = ConvexPolygon::fromPoints(points);
  EXPECT_TRUE(p.has_value());
  return p.value_or(ConvexPolygon{});
}

// Three parked cars at odd angles, then a triangle, a wall and a hexagon, all within a few metres
// of the origin so that random player boxes there meet every kind of collider.
Scene mixedScene() {
  Scene s;
  s.name = "mixed";
  s.player.position = {-30.0, -30.0};
  s.parked.push_back({"car-a", Obb2::fromDegrees({-4.0, 1.0}, 17.0, 4.5, 1.8), 17.0});
  s.parked.push_back({"car-b", Obb2::fromDegrees({3.0, -2.5}, -95.0, 4.2, 1.7), -95.0});
  s.parked.push_back({"car-c", Obb2::fromDegrees({0.5, 4.0}, 180.0, 4.8, 2.0), 180.0});
  s.obstacles.push_back({"tri", polygonThrough({{5.0, 2.0}, {8.0, 3.0}, {6.0, 6.0}})});
  s.obstacles.push_back({"wall", polygonThrough({{-8.0, -6.0}, {-2.0, -6.0}, {-2.0, -5.5}})});
  std::vector<Eigen::Vector2d> hexagon;
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector2d d = unitFromDegrees(60.0 * k + 7.0);
    hexagon.push_back(Eigen::Vector2d{-1.0, -1.0} + 1.5 * d);
  }
  s.obstacles.push_back({"hex", polygonThrough(hexagon)});
  return s;
}

TEST(StaticColliders, BoxesFirstThenPolygonsInSceneOrder) {
  const Scene scene = mixedScene();
  const World world(scene);
  const StaticColliders& c = world.colliders();
  ASSERT_EQ(c.size(), 6u);
  ASSERT_EQ(c.boxCount(), 3u);
  for (std::uint32_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(c.isBox(i)) << i;
    EXPECT_TRUE(sameObb(c.box(i), scene.parked[i].box)) << i;
    EXPECT_TRUE(std::holds_alternative<Obb2>(c.shape(i))) << i;
    EXPECT_TRUE(sameObb(std::get<Obb2>(c.shape(i)), scene.parked[i].box)) << i;
    EXPECT_EQ(world.colliderId(i), scene.parked[i].id);
  }
  for (std::uint32_t i = 3; i < 6; ++i) {
    const Obstacle& o = scene.obstacles[i - 3];
    EXPECT_FALSE(c.isBox(i)) << i;
    EXPECT_TRUE(samePolygon(c.polygon(i), o.polygon)) << i;
    EXPECT_TRUE(std::holds_alternative<ConvexPolygon>(c.shape(i))) << i;
    EXPECT_TRUE(samePolygon(std::get<ConvexPolygon>(c.shape(i)), o.polygon)) << i;
    EXPECT_EQ(world.colliderId(i), o.id);
  }
}

TEST(StaticColliders, VisitPassesTheStoredShapeByKind) {
  const StaticColliders c = World(mixedScene()).colliders();
  for (std::uint32_t i = 0; i < c.size(); ++i) {
    const bool got_box =
        c.visit(i, [](const auto& s) { return std::is_same_v<std::decay_t<decltype(s)>, Obb2>; });
    EXPECT_EQ(got_box, c.isBox(i)) << i;
    // The reference handed over is the stored shape itself, not a copy.
    const void* address = c.visit(i, [](const auto& s) { return static_cast<const void*>(&s); });
    if (c.isBox(i)) {
      EXPECT_EQ(address, &c.box(i)) << i;
    } else {
      EXPECT_EQ(address, &c.polygon(i)) << i;
    }
  }
}

TEST(StaticColliders, VisitGivesTheVariantDispatchBitForBit) {
  const StaticColliders c = World(mixedScene()).colliders();
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> pos(-9.0, 9.0), deg(-180.0, 180.0), len(3.0, 5.5),
      wid(1.4, 2.2), step(-3.0, 3.0);
  int overlapping = 0;
  for (int n = 0; n < 4000; ++n) {
    const Eigen::Vector2d center{pos(rng), pos(rng)};
    const double heading = deg(rng);
    const double length = len(rng);
    const double width = wid(rng);
    const Obb2 player = Obb2::fromDegrees(center, heading, length, width);
    const Eigen::Vector2d displacement{step(rng), step(rng)};
    const Eigen::Vector2d axis = unitFromDegrees(deg(rng));
    for (std::uint32_t i = 0; i < c.size(); ++i) {
      const StaticShape shape = c.shape(i);
      const SatResult2 want = collidePlayer(player, shape);
      const SatResult2 got = c.visit(i, [&](const auto& s) { return collidePlayer(player, s); });
      ASSERT_EQ(got.hit, want.hit) << "case " << n << ", collider " << i;
      ASSERT_EQ(bitsOf(got.separation), bitsOf(want.separation)) << "case " << n << ", " << i;
      ASSERT_EQ(bitsOf(got.normal.x()), bitsOf(want.normal.x())) << "case " << n << ", " << i;
      ASSERT_EQ(bitsOf(got.normal.y()), bitsOf(want.normal.y())) << "case " << n << ", " << i;
      if (want.hit) ++overlapping;

      const double along =
          c.visit(i, [&](const auto& s) { return separationAlong(player, s, axis); });
      ASSERT_EQ(bitsOf(along), bitsOf(separationAlong(player, shape, axis))) << n << ", " << i;

      const SweepResult2 swept = sweepPlayer(player, displacement, shape);
      const SweepResult2 visited =
          c.visit(i, [&](const auto& s) { return sweepPlayer(player, displacement, s); });
      ASSERT_EQ(visited.hit, swept.hit) << "case " << n << ", collider " << i;
      ASSERT_EQ(bitsOf(visited.toi), bitsOf(swept.toi)) << "case " << n << ", " << i;
      ASSERT_EQ(bitsOf(visited.normal.x()), bitsOf(swept.normal.x())) << n << ", " << i;
      ASSERT_EQ(bitsOf(visited.normal.y()), bitsOf(swept.normal.y())) << n << ", " << i;
      ASSERT_EQ(bitsOf(visited.start_separation), bitsOf(swept.start_separation)) << n << ", " << i;
    }
  }
  // The draws reach the colliders often enough for the contact branch to be tested too.
  EXPECT_GT(overlapping, 1000);
}

TEST(StaticColliders, BoundsAreTheTightBoundsOfEachShape) {
  const StaticColliders c = World(mixedScene()).colliders();
  ASSERT_EQ(c.bounds().size(), c.size());
  for (std::uint32_t i = 0; i < c.size(); ++i) {
    EXPECT_TRUE(sameBounds(c.bounds(i), boundsOf(c.shape(i)))) << i;
    EXPECT_TRUE(sameBounds(c.bounds()[i], c.bounds(i))) << i;
    const Aabb2 tight = c.isBox(i) ? c.box(i).aabb() : c.polygon(i).aabb();
    EXPECT_TRUE(sameBounds(c.bounds(i), tight)) << i;
  }
}

TEST(StaticColliders, EmptyAndPolygonOnly) {
  const StaticColliders none;
  EXPECT_EQ(none.size(), 0u);
  EXPECT_EQ(none.boxCount(), 0u);
  EXPECT_TRUE(none.bounds().empty());

  const ConvexPolygon square =
      ConvexPolygon::fromObb(Obb2::fromDegrees({2.0, 3.0}, 30.0, 2.0, 1.0));
  const StaticColliders polygons({}, {square, square});
  EXPECT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons.boxCount(), 0u);
  EXPECT_FALSE(polygons.isBox(0));
  EXPECT_TRUE(samePolygon(polygons.polygon(1), square));
  EXPECT_TRUE(sameBounds(polygons.bounds(0), square.aabb()));
}

}  // namespace
}  // namespace cardemo
