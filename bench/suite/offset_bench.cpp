// Cost per pair at a distance from the world origin, like for like: cardemo's overlapObb2 against
// Box2D's b2TestOverlap (booleans), manifoldObb2 against b2CollidePolygons (contact manifolds), and
// collideObb2 (depth and normal, no Box2D equivalent); Box2D with float world transforms, skin 0,
// on the same 1k random pairs moved by 0, 1e3, 1e5 and 1e7 m. scripts/plot_cost_error.py puts
// this cost against the misclassification rate that `cardemo compare-sweep` measures.

#include <benchmark/benchmark.h>

#include <cstdio>

#include "bench_registry.hpp"
#include "geometry/sat_obb2.hpp"
#include "lab/kernels/manifold2.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include "compare/box2d/box2d_shapes.hpp"
#endif

namespace cardemo::bench {
namespace {

constexpr std::size_t kPairs = 1000;

// The 1k narrow-phase pairs, both boxes moved by `offset` along a diagonal.
PairSet2 movedPairs(double offset) {
  PairSet2 out = pairSet2(kPairs);
  const Eigen::Vector2d shift = offset * Eigen::Vector2d(0.6, 0.8);
  for (Obb2& box : out.a) box.center += shift;
  for (Obb2& box : out.b) box.center += shift;
  return out;
}

template <class PerPair>
void overPairs(benchmark::State& state, const PerPair& per_pair) {
  double sink = 0.0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < kPairs; ++i) sink += per_pair(i);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(kPairs));
}

}  // namespace

void registerOffset(const BenchConfig& /*config*/) {
  // Named offset/QUERY/OFFSET/ENGINE, each Box2D query under its cardemo like-for-like: the
  // boolean b2TestOverlap beside overlapObb2, the manifold b2CollidePolygons beside manifoldObb2.
  for (const double offset : {0.0, 1e3, 1e5, 1e7}) {
    char label[32];
    std::snprintf(label, sizeof label, "%g", offset);
    const auto name = [&label](const char* query, const char* engine) {
      return std::string("offset/") + query + "/" + label + "/" + engine;
    };
    benchmark::RegisterBenchmark(
        name("overlapObb2", "cardemo").c_str(), [offset](benchmark::State& s) {
          const PairSet2 p = movedPairs(offset);
          overPairs(s, [&p](std::size_t i) { return overlapObb2(p.a[i], p.b[i]) ? 1.0 : 0.0; });
        });
    benchmark::RegisterBenchmark(
        name("collideObb2", "cardemo").c_str(), [offset](benchmark::State& s) {
          const PairSet2 p = movedPairs(offset);
          overPairs(s, [&p](std::size_t i) { return collideObb2(p.a[i], p.b[i]).separation; });
        });
    benchmark::RegisterBenchmark(name("manifoldObb2", "cardemo").c_str(),
                                 [offset](benchmark::State& s) {
                                   const PairSet2 p = movedPairs(offset);
                                   overPairs(s, [&p](std::size_t i) {
                                     const Manifold2 m = manifoldObb2(p.a[i], p.b[i]);
                                     return static_cast<double>(m.count) + m.normal.x();
                                   });
                                 });
#if defined(CARDEMO_HAVE_COMPARE)
    const auto box2d = [offset](benchmark::State& s, bool gjk) {
      const PairSet2 p = movedPairs(offset);
      std::vector<compare::Box2dShape> a, b;
      for (std::size_t i = 0; i < kPairs; ++i) {
        a.push_back(compare::box2dBox(p.a[i], 0.0f));
        b.push_back(compare::box2dBox(p.b[i], 0.0f));
      }
      if (gjk) {
        overPairs(s, [&](std::size_t i) {
          return b2TestOverlap(&a[i].shape, 0, &b[i].shape, 0, a[i].xf, b[i].xf) ? 1.0 : 0.0;
        });
      } else {
        overPairs(s, [&](std::size_t i) {
          b2Manifold m;
          b2CollidePolygons(&m, &a[i].shape, a[i].xf, &b[i].shape, b[i].xf);
          return static_cast<double>(m.pointCount) + m.localNormal.x;
        });
      }
    };
    benchmark::RegisterBenchmark(name("overlapObb2", "box2d").c_str(),
                                 [box2d](benchmark::State& s) { box2d(s, true); });
    benchmark::RegisterBenchmark(name("manifoldObb2", "box2d").c_str(),
                                 [box2d](benchmark::State& s) { box2d(s, false); });
#endif
  }
}

}  // namespace cardemo::bench
