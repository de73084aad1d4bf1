// Cost per pair at a distance from the world origin: cardemo's collideObb2 against Box2D's
// b2CollidePolygons and b2TestOverlap (float world transforms, skin 0) on the same 1k random pairs
// moved by 0, 1e3, 1e5 and 1e7 m. These are the verdicts `cardemo compare-sweep` holds to the
// exact oracle; scripts/plot_cost_error.py puts this cost against that misclassification rate.

#include <benchmark/benchmark.h>

#include <cstdio>

#include "bench_registry.hpp"
#include "geometry/sat_obb2.hpp"

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
  for (const double offset : {0.0, 1e3, 1e5, 1e7}) {
    char label[32];
    std::snprintf(label, sizeof label, "%g", offset);
    const std::string prefix = std::string("offset/collideObb2/") + label + "/";
    benchmark::RegisterBenchmark((prefix + "cardemo").c_str(), [offset](benchmark::State& s) {
      const PairSet2 p = movedPairs(offset);
      overPairs(s, [&p](std::size_t i) { return collideObb2(p.a[i], p.b[i]).separation; });
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
    benchmark::RegisterBenchmark((prefix + "box2d").c_str(),
                                 [box2d](benchmark::State& s) { box2d(s, false); });
    benchmark::RegisterBenchmark((prefix + "box2d_overlap").c_str(),
                                 [box2d](benchmark::State& s) { box2d(s, true); });
#endif
  }
}

}  // namespace cardemo::bench
