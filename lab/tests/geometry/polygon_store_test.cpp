#include "lab/geometry/polygon_store.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "tests/geometry/random_cases2.hpp"

namespace cardemo {
namespace {

using testing::Random;

TEST(PolygonStore, ViewsHoldTheAddedVerticesInOrder) {
  Random rng(3001);
  std::vector<ConvexPolygon> added;
  PolygonStore store;
  for (int i = 0; i < 200; ++i) {
    added.push_back(rng.polygon(rng.farPoint(1e7), 0.1, 20.0));
    EXPECT_EQ(store.add(added.back()), added.size() - 1);
  }
  ASSERT_EQ(store.size(), added.size());
  for (std::size_t i = 0; i < added.size(); ++i) {
    const PolygonView view = store[i];
    ASSERT_EQ(view.count, added[i].count) << "polygon " << i;
    for (int k = 0; k < view.count; ++k) {
      EXPECT_EQ(view.vertex(k), added[i].vertex(k)) << "polygon " << i << " vertex " << k;
    }
  }
}

TEST(PolygonStore, QueriesOnViewsEqualQueriesOnPolygons) {
  Random rng(3002);
  PolygonStore store;
  std::vector<ConvexPolygon> polygons;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector2d c = rng.farPoint(1e7);
    polygons.push_back(i % 2 == 0 ? rng.quadrilateral(c, 0.1, 20.0) : rng.polygon(c, 0.1, 20.0));
    polygons.push_back(rng.polygon(c + rng.offset(0, 20), 0.1, 20.0));
  }
  store.reserve(polygons.size(), 16 * polygons.size());
  for (const ConvexPolygon& p : polygons) store.add(p);
  for (std::size_t i = 0; i + 1 < polygons.size(); i += 2) {
    const SatResult2 want = collidePolygons(polygons[i], polygons[i + 1]);
    const SatResult2 got = collidePolygons(store[i], store[i + 1]);
    EXPECT_EQ(got.hit, want.hit) << "pair " << i;
    EXPECT_EQ(got.separation, want.separation) << "pair " << i;
    EXPECT_EQ(got.normal, want.normal) << "pair " << i;
  }
}

TEST(PolygonStore, RejectsTooFewOrTooManyVertices) {
  PolygonStore store;
  const std::vector<Eigen::Vector2d> points(ConvexPolygon::kMaxVertices + 1,
                                            Eigen::Vector2d::Zero());
  EXPECT_THROW(store.add(PolygonView{points.data(), 2}), std::invalid_argument);
  EXPECT_THROW(store.add(PolygonView{points.data(), ConvexPolygon::kMaxVertices + 1}),
               std::invalid_argument);
  EXPECT_EQ(store.size(), 0u);
}

}  // namespace
}  // namespace cardemo
