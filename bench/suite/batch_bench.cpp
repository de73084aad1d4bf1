// Batch kernels: one box against many (struct of arrays), on each dispatch path, with the scalar
// loop and Box2D on the same boxes for reference. 64k boxes (so that no iteration replays a
// short sequence the branch predictor has learnt) and 1M; a tenth of the boxes (2D and 3D) lie
// within 1e-5 m of touching the query box, so the float pre-filters send some on and the double
// fallback is in the time.

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "bench_registry.hpp"
#include "geometry/batch_path.hpp"
#include "geometry/sat_obb2.hpp"
#include "lab/geometry/kernel_paths.hpp"
#include "lab/kernels/obb2_batch.hpp"
#include "lab/kernels/obb3_batch.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include "compare/box2d/box2d_shapes.hpp"
#endif

namespace cardemo::bench {
namespace {

const Obb2Batch& batch2(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Obb2Batch>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<Obb2Batch>(batchSet2(n).b);
  return *slot;
}

const Obb3Batch& batch3(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Obb3Batch>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<Obb3Batch>(batchSet3(n).b);
  return *slot;
}

// Runs `body()` (one pass over all n boxes) per iteration on `path`; items are pairs.
template <class Body>
void onPath(benchmark::State& state, BatchPath path, std::size_t n, double share,
            const Body& body) {
  const BatchPath saved = batchPath();
  setBatchPath(path);
  for (auto _ : state) body();
  setBatchPath(saved);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  state.counters["overlap_share"] = share;
}

void registerSize(std::size_t n) {
  const std::string size = sizeLabel(n);
  const auto name = [&size](const char* query, const char* engine) {
    return std::string("batch/") + query + "/" + size + "/" + engine;
  };
  for (const BatchPath path : {BatchPath::kAvx512, BatchPath::kAvx2, BatchPath::kPortable}) {
    // Only the paths this CPU has: a skipped benchmark prints the smoke test's failure pattern.
    if (!batchPathAvailable(path) || !kernelsBuiltFor(path)) continue;
    const char* engine = batchPathName(path);
    benchmark::RegisterBenchmark(
        name("overlapObb2", engine).c_str(), [n, path](benchmark::State& s) {
          const PairSet2& set = batchSet2(n);
          const Obb2Batch& many = batch2(n);
          std::vector<std::uint8_t> hit(n);
          std::size_t sent_on = 0;
          onPath(s, path, n, set.overlap_share, [&] {
            sent_on = overlapObb2Batch(set.a[0], many, hit);
            benchmark::DoNotOptimize(hit.data());
            benchmark::ClobberMemory();
          });
          // Share of the pairs the float pre-filter left to the double kernel (0 without a
          // filter, as on the portable path).
          s.counters["sent_on_share"] = static_cast<double>(sent_on) / static_cast<double>(n);
        });
    benchmark::RegisterBenchmark(name("collideObb2", engine).c_str(),
                                 [n, path](benchmark::State& s) {
                                   const PairSet2& set = batchSet2(n);
                                   const Obb2Batch& many = batch2(n);
                                   std::vector<double> sep(n), nx(n), ny(n);
                                   onPath(s, path, n, set.overlap_share, [&] {
                                     collideObb2Batch(set.a[0], many, sep, nx, ny);
                                     benchmark::DoNotOptimize(sep.data());
                                     benchmark::ClobberMemory();
                                   });
                                 });
    benchmark::RegisterBenchmark(
        name("overlapObb3", engine).c_str(), [n, path](benchmark::State& s) {
          const PairSet3& set = batchSet3(n);
          const Obb3Batch& many = batch3(n);
          std::vector<std::uint8_t> hit(n);
          std::size_t sent_on = 0;
          onPath(s, path, n, set.overlap_share, [&] {
            sent_on = overlapObb3Batch(set.a[0], many, hit);
            benchmark::DoNotOptimize(hit.data());
            benchmark::ClobberMemory();
          });
          s.counters["sent_on_share"] = static_cast<double>(sent_on) / static_cast<double>(n);
        });
    benchmark::RegisterBenchmark(name("separationObb3", engine).c_str(),
                                 [n, path](benchmark::State& s) {
                                   const PairSet3& set = batchSet3(n);
                                   const Obb3Batch& many = batch3(n);
                                   std::vector<double> sep(n);
                                   onPath(s, path, n, set.overlap_share, [&] {
                                     separationObb3Batch(set.a[0], many, sep);
                                     benchmark::DoNotOptimize(sep.data());
                                     benchmark::ClobberMemory();
                                   });
                                 });
  }
  // The scalar functions on the same one-against-many data (what the batch replaces).
  const auto scalar = [n](benchmark::State& s, double share, const auto& per_box) {
    double sink = 0.0;
    for (auto _ : s) {
      for (std::size_t i = 0; i < n; ++i) sink += per_box(i);
      benchmark::DoNotOptimize(sink);
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) * static_cast<std::int64_t>(n));
    s.counters["overlap_share"] = share;
  };
  benchmark::RegisterBenchmark(
      name("overlapObb2", "scalar").c_str(), [n, scalar](benchmark::State& s) {
        const PairSet2& set = batchSet2(n);
        scalar(s, set.overlap_share,
               [&set](std::size_t i) { return overlapObb2(set.a[0], set.b[i]) ? 1.0 : 0.0; });
      });
  benchmark::RegisterBenchmark(
      name("collideObb2", "scalar").c_str(), [n, scalar](benchmark::State& s) {
        const PairSet2& set = batchSet2(n);
        scalar(s, set.overlap_share,
               [&set](std::size_t i) { return collideObb2(set.a[0], set.b[i]).separation; });
      });
  benchmark::RegisterBenchmark(
      name("overlapObb3", "scalar").c_str(), [n, scalar](benchmark::State& s) {
        const PairSet3& set = batchSet3(n);
        scalar(s, set.overlap_share,
               [&set](std::size_t i) { return overlapObb3(set.a[0], set.b[i]) ? 1.0 : 0.0; });
      });
  benchmark::RegisterBenchmark(
      name("separationObb3", "scalar").c_str(), [n, scalar](benchmark::State& s) {
        const PairSet3& set = batchSet3(n);
        scalar(s, set.overlap_share,
               [&set](std::size_t i) { return collideObb3(set.a[0], set.b[i]).separation; });
      });
#if defined(CARDEMO_HAVE_COMPARE)
  benchmark::RegisterBenchmark(
      name("overlapObb2", "box2d").c_str(), [n, scalar](benchmark::State& s) {
        const PairSet2& set = batchSet2(n);
        const compare::Box2dShape a = compare::box2dBox(set.a[0], 0.0f);
        std::vector<compare::Box2dShape> b;
        for (const Obb2& box : set.b) b.push_back(compare::box2dBox(box, 0.0f));
        scalar(s, set.overlap_share, [&](std::size_t i) {
          return b2TestOverlap(&a.shape, 0, &b[i].shape, 0, a.xf, b[i].xf) ? 1.0 : 0.0;
        });
      });
  benchmark::RegisterBenchmark(name("collideObb2", "box2d").c_str(),
                               [n, scalar](benchmark::State& s) {
                                 const PairSet2& set = batchSet2(n);
                                 const compare::Box2dShape a = compare::box2dBox(set.a[0], 0.0f);
                                 std::vector<compare::Box2dShape> b;
                                 for (const Obb2& box : set.b)
                                   b.push_back(compare::box2dBox(box, 0.0f));
                                 scalar(s, set.overlap_share, [&](std::size_t i) {
                                   b2Manifold m;
                                   b2CollidePolygons(&m, &a.shape, a.xf, &b[i].shape, b[i].xf);
                                   return static_cast<double>(m.pointCount);
                                 });
                               });
#endif
}

}  // namespace

void registerBatch(const BenchConfig& config) {
  for (const std::size_t n :
       {config.smoke ? std::size_t{1000} : 64000, config.smoke ? std::size_t{10000} : 1000000}) {
    registerSize(n);
  }
}

}  // namespace cardemo::bench
