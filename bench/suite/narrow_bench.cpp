// Narrow phase, one pair at a time: every cardemo pair query and Box2D's on the same random pairs
// (about 45% overlapping, in random order), 1k pairs (in cache, their branch pattern partly
// learned), 64k (in cache, not learned) and 1M pairs (in memory).

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "bench_registry.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"
#include "lab/geometry/collide_quads.hpp"
#include "lab/geometry/obb3_paths.hpp"
#include "lab/geometry/polygon_store.hpp"
#include "lab/kernels/manifold2.hpp"
#include "lab/kernels/manifold2_batch.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include "compare/box2d/box2d_shapes.hpp"
#endif

namespace cardemo::bench {
namespace {

// Packed as a scene of many polygons would be (68 bytes a quadrilateral; a ConvexPolygon has room
// for 16 vertices, 272 bytes).
struct PolygonPairs {
  PolygonStore a, b;
};

const PolygonPairs& polygonPairs(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<PolygonPairs>> cache;
  auto& slot = cache[n];
  if (!slot) {
    slot = std::make_unique<PolygonPairs>();
    const PairSet2& set = pairSet2(n);
    slot->a.reserve(n, 4 * n);
    slot->b.reserve(n, 4 * n);
    for (std::size_t i = 0; i < n; ++i) {
      slot->a.add(ConvexPolygon::fromObb(set.a[i]));
      slot->b.add(ConvexPolygon::fromObb(set.b[i]));
    }
  }
  return *slot;
}

// Runs `per_pair(i)` over every pair each iteration; items are pairs. One untimed pass comes
// first: in a run whose repetitions are interleaved, a row's data may have gone cold in between,
// and on this VM the first pass over Box2D's 1M pairs then took 4x the next ones.
template <class PerPair>
void overPairs(benchmark::State& state, std::size_t n, double overlap_share,
               const PerPair& per_pair) {
  double sink = 0.0;
  for (std::size_t i = 0; i < n; ++i) sink += per_pair(i);
  benchmark::DoNotOptimize(sink);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) sink += per_pair(i);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  state.counters["overlap_share"] = overlap_share;
}

// The same pairs as struct-of-arrays batches, and room for their manifolds.
struct BatchPairs {
  Obb2Batch a, b;
  Manifold2Batch out;
};

BatchPairs& batchPairs(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<BatchPairs>> cache;
  auto& slot = cache[n];
  if (!slot) {
    const PairSet2& set = pairSet2(n);
    slot = std::make_unique<BatchPairs>(BatchPairs{Obb2Batch(set.a), Obb2Batch(set.b), {}});
    slot->out.resize(n);
  }
  return *slot;
}

#if defined(CARDEMO_HAVE_COMPARE)
struct Box2dPairs {
  std::vector<compare::Box2dShape> a, b;
};

const Box2dPairs& box2dPairs(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Box2dPairs>> cache;
  auto& slot = cache[n];
  if (!slot) {
    slot = std::make_unique<Box2dPairs>();
    const PairSet2& set = pairSet2(n);
    for (std::size_t i = 0; i < n; ++i) {
      slot->a.push_back(compare::box2dBox(set.a[i], 0.0f));
      slot->b.push_back(compare::box2dBox(set.b[i], 0.0f));
    }
  }
  return *slot;
}
#endif

void registerSize(std::size_t n) {
  const std::string size = sizeLabel(n);
  const auto name = [&size](const char* query, const char* engine) {
    return std::string("narrow/") + query + "/" + size + "/" + engine;
  };
  benchmark::RegisterBenchmark(name("overlapObb2", "cardemo").c_str(), [n](benchmark::State& s) {
    const PairSet2& p = pairSet2(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return overlapObb2(p.a[i], p.b[i]) ? 1.0 : 0.0; });
  });
  benchmark::RegisterBenchmark(name("collideObb2", "cardemo").c_str(), [n](benchmark::State& s) {
    const PairSet2& p = pairSet2(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return collideObb2(p.a[i], p.b[i]).separation; });
  });
  benchmark::RegisterBenchmark(name("manifoldObb2", "cardemo").c_str(), [n](benchmark::State& s) {
    const PairSet2& p = pairSet2(n);
    overPairs(s, n, p.overlap_share, [&p](std::size_t i) {
      const Manifold2 m = manifoldObb2(p.a[i], p.b[i]);
      return static_cast<double>(m.count) + m.normal.x();
    });
  });
  // Every pair's manifold written to memory (struct of arrays), on the widest batch path: four
  // pairs per AVX2 instruction, eight per AVX-512 one.
  benchmark::RegisterBenchmark(name("manifoldObb2Batch", "cardemo").c_str(),
                               [n](benchmark::State& s) {
                                 BatchPairs& p = batchPairs(n);
                                 double sink = 0.0;
                                 for (auto _ : s) {
                                   manifoldObb2Batch(p.a, p.b, p.out);
                                   const Manifold2 last = p.out.manifold(n - 1);
                                   sink += static_cast<double>(last.count) + last.normal.x();
                                   benchmark::DoNotOptimize(sink);
                                   benchmark::ClobberMemory();
                                 }
                                 s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) *
                                                     static_cast<std::int64_t>(n));
                                 s.counters["overlap_share"] = pairSet2(n).overlap_share;
                               });
  benchmark::RegisterBenchmark(
      name("collidePolygons", "cardemo").c_str(), [n](benchmark::State& s) {
        const PolygonPairs& p = polygonPairs(n);
        overPairs(s, n, pairSet2(n).overlap_share,
                  [&p](std::size_t i) { return collidePolygons(p.a[i], p.b[i]).separation; });
      });
  // The lab's variants of the same queries (lab/geometry), on the widest batch path: the same bits.
  benchmark::RegisterBenchmark(name("collidePolygons", "lab").c_str(), [n](benchmark::State& s) {
    const PolygonPairs& p = polygonPairs(n);
    overPairs(s, n, pairSet2(n).overlap_share,
              [&p](std::size_t i) { return collideQuads(p.a[i], p.b[i]).separation; });
  });
  benchmark::RegisterBenchmark(name("overlapObb3", "lab").c_str(), [n](benchmark::State& s) {
    const PairSet3& p = pairSet3(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return overlapObb3OnPath(p.a[i], p.b[i]) ? 1.0 : 0.0; });
  });
  benchmark::RegisterBenchmark(name("collideObb3", "lab").c_str(), [n](benchmark::State& s) {
    const PairSet3& p = pairSet3(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return collideObb3OnPath(p.a[i], p.b[i]).separation; });
  });
  benchmark::RegisterBenchmark(name("overlapObb3", "cardemo").c_str(), [n](benchmark::State& s) {
    const PairSet3& p = pairSet3(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return overlapObb3(p.a[i], p.b[i]) ? 1.0 : 0.0; });
  });
  benchmark::RegisterBenchmark(name("collideObb3", "cardemo").c_str(), [n](benchmark::State& s) {
    const PairSet3& p = pairSet3(n);
    overPairs(s, n, p.overlap_share,
              [&p](std::size_t i) { return collideObb3(p.a[i], p.b[i]).separation; });
  });
#if defined(CARDEMO_HAVE_COMPARE)
  // Box2D 2.4.1 as its users call it: float world transforms, skin 0 (compare/box2d).
  benchmark::RegisterBenchmark(name("overlapObb2", "box2d").c_str(), [n](benchmark::State& s) {
    const Box2dPairs& p = box2dPairs(n);
    overPairs(s, n, pairSet2(n).overlap_share, [&p](std::size_t i) {
      return b2TestOverlap(&p.a[i].shape, 0, &p.b[i].shape, 0, p.a[i].xf, p.b[i].xf) ? 1.0 : 0.0;
    });
  });
  // Box2D's like-for-like of manifoldObb2, manifoldObb2Batch and collidePolygons (all on these
  // pairs): registered once, so that every ratio divides by the same measurement.
  benchmark::RegisterBenchmark(name("collidePolygons", "box2d").c_str(), [n](benchmark::State& s) {
    const Box2dPairs& p = box2dPairs(n);
    overPairs(s, n, pairSet2(n).overlap_share, [&p](std::size_t i) {
      b2Manifold m;
      b2CollidePolygons(&m, &p.a[i].shape, p.a[i].xf, &p.b[i].shape, p.b[i].xf);
      return static_cast<double>(m.pointCount) + m.localNormal.x;
    });
  });
#endif
}

}  // namespace

// 1k pairs stay in L1/L2 and repeat every iteration, so the branch predictor learns part of their
// sequence; 64k pairs still fit in L3 but repeat too rarely to be learned; 1M pairs come from
// memory. 64k against 1k shows what the predictor gives, 1M against 64k what memory costs.
void registerNarrow(const BenchConfig& config) {
  const std::size_t sizes[] = {1000, 64000, config.smoke ? std::size_t{10000} : 1000000};
  for (const std::size_t n : sizes) {
    if (config.smoke && n == 64000) continue;
    registerSize(n);
  }
}

}  // namespace cardemo::bench
