// Broad phase over N parked cars (a lot layout and a random one): build time per car, query time
// for a car-sized box moving through the lot, and bytes per car; UniformGrid against Box2D's
// b2DynamicTree (CreateProxy per box, Query with a callback) on the same boxes.

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <utility>

#include "bench_registry.hpp"
#include "collision/broad_phase.hpp"

#if defined(CARDEMO_HAVE_COMPARE)
#include <box2d/b2_dynamic_tree.h>
#endif

namespace cardemo::bench {
namespace {

constexpr std::size_t kPathSteps = 8192;

struct Lot {
  std::vector<Aabb2> boxes;
  std::vector<Aabb2> path;
};

const Lot& lot(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<Lot>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) {
    slot = std::make_unique<Lot>();
    slot->boxes = boundsOf(random ? randomLayout(n) : lotLayout(n));
    slot->path = queryPath(slot->boxes, kPathSteps);
  }
  return *slot;
}

const UniformGrid& grid(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<UniformGrid>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) slot = std::make_unique<UniformGrid>(lot(random, n).boxes);
  return *slot;
}

#if defined(CARDEMO_HAVE_COMPARE)
b2AABB toB2(const Aabb2& b) {
  b2AABB a;
  a.lowerBound.Set(static_cast<float>(b.min.x()), static_cast<float>(b.min.y()));
  a.upperBound.Set(static_cast<float>(b.max.x()), static_cast<float>(b.max.y()));
  return a;
}

void fillTree(b2DynamicTree& tree, const std::vector<Aabb2>& boxes) {
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    // The user data is the car index, as a b2World's fixture proxy would carry its fixture.
    tree.CreateProxy(toB2(boxes[i]), reinterpret_cast<void*>(i + 1));
  }
}

const b2DynamicTree& tree(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<b2DynamicTree>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) {
    slot = std::make_unique<b2DynamicTree>();
    fillTree(*slot, lot(random, n).boxes);
  }
  return *slot;
}

// Collects the car index of every proxy whose (fattened) box overlaps the query.
struct TreeCollector {
  const b2DynamicTree* tree = nullptr;
  std::vector<std::uint32_t>* out = nullptr;
  bool QueryCallback(int32 proxy) {
    out->push_back(
        static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)) - 1));
    return true;
  }
};
#endif

void registerLayout(bool random, std::size_t n) {
  const std::string prefix = std::string(random ? "random/" : "lot/") + sizeLabel(n) + "/";
  benchmark::RegisterBenchmark(
      ("broad/build/" + prefix + "cardemo").c_str(), [random, n](benchmark::State& s) {
        const Lot& l = lot(random, n);
        std::size_t bytes = 0;
        for (auto _ : s) {
          const UniformGrid g(l.boxes);
          bytes = g.memoryBytes();
          benchmark::DoNotOptimize(bytes);
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) *
                            static_cast<std::int64_t>(n));
        s.counters["bytes_per_car"] = static_cast<double>(bytes) / static_cast<double>(n);
      });
  benchmark::RegisterBenchmark(
      ("broad/query/" + prefix + "cardemo").c_str(), [random, n](benchmark::State& s) {
        const Lot& l = lot(random, n);
        const UniformGrid& g = grid(random, n);
        // QueryIds, as World::step queries the grid.
        QueryIds out;
        out.reserve(4096);
        std::size_t step = 0, found = 0;
        for (auto _ : s) {
          g.query(l.path[step], out);
          found += out.size();
          step = (step + 1) % l.path.size();
          benchmark::DoNotOptimize(out.begin());
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
        s.counters["candidates"] = static_cast<double>(found) /
                                   static_cast<double>(std::max<std::int64_t>(1, s.iterations()));
        s.counters["bytes_per_car"] = static_cast<double>(g.memoryBytes()) / static_cast<double>(n);
        s.counters["cell_m"] = g.levelCount() > 0 ? g.cellSize(0) : 0.0;
      });
#if defined(CARDEMO_HAVE_COMPARE)
  benchmark::RegisterBenchmark(
      ("broad/build/" + prefix + "box2d").c_str(), [random, n](benchmark::State& s) {
        const Lot& l = lot(random, n);
        for (auto _ : s) {
          b2DynamicTree t;
          fillTree(t, l.boxes);
          benchmark::DoNotOptimize(t.GetHeight());
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) *
                            static_cast<std::int64_t>(n));
        // A tree over N leaves has 2N - 1 nodes; Box2D allocates at least that many.
        s.counters["bytes_per_car"] =
            static_cast<double>((2 * n - 1) * sizeof(b2TreeNode)) / static_cast<double>(n);
      });
  benchmark::RegisterBenchmark(
      ("broad/query/" + prefix + "box2d").c_str(), [random, n](benchmark::State& s) {
        const Lot& l = lot(random, n);
        const b2DynamicTree& t = tree(random, n);
        std::vector<std::uint32_t> out;
        out.reserve(4096);
        TreeCollector collector{&t, &out};
        std::size_t step = 0, found = 0;
        for (auto _ : s) {
          out.clear();
          t.Query(&collector, toB2(l.path[step]));
          found += out.size();
          step = (step + 1) % l.path.size();
          benchmark::DoNotOptimize(out.data());
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
        s.counters["candidates"] = static_cast<double>(found) /
                                   static_cast<double>(std::max<std::int64_t>(1, s.iterations()));
        s.counters["bytes_per_car"] =
            static_cast<double>((2 * n - 1) * sizeof(b2TreeNode)) / static_cast<double>(n);
      });
#endif
}

}  // namespace

void registerBroad(const BenchConfig& config) {
  const std::vector<std::size_t> sizes =
      config.smoke ? std::vector<std::size_t>{100, 1000}
                   : std::vector<std::size_t>{100, 1000, 10000, 100000, 1000000};
  for (const bool random : {false, true}) {
    for (const std::size_t n : sizes) registerLayout(random, n);
  }
}

}  // namespace cardemo::bench
