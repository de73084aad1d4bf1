// Broad phase over N parked cars (a lot layout and a random one): build time per car, query time
// for a car-sized box moving through the lot (and, at the largest size, for boxes scattered over
// it), and bytes per car; UniformGrid against Box2D's
// b2DynamicTree (CreateProxy per box in a spatially coherent order, Query with a callback) on the
// same boxes.

#include <benchmark/benchmark.h>

#include <algorithm>
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

// Scattered queries per row: 2^20 boxes (32 MiB), more than the caches hold with the grid or the
// tree, so each query finds its part of the structure cold, as queries spread over a large world
// (many cars, or a car teleported) would.
constexpr std::size_t kScatteredQueries = std::size_t{1} << 20;

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

// The path through the lot, as the game's car queries it.
const std::vector<Aabb2>& pathOf(bool random, std::size_t n) {
  return lot(random, n).path;
}

// kScatteredQueries boxes spread over the lot (bench_data's scatteredQueries), made once.
const std::vector<Aabb2>& scatteredOf(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<std::vector<Aabb2>>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) {
    slot = std::make_unique<std::vector<Aabb2>>(
        scatteredQueries(lot(random, n).boxes, kScatteredQueries));
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

// Spreads the low 16 bits of v to the even bits of the result.
std::uint32_t spreadBits(std::uint32_t v) {
  v &= 0xFFFFu;
  v = (v | (v << 8)) & 0x00FF00FFu;
  v = (v | (v << 4)) & 0x0F0F0F0Fu;
  v = (v | (v << 2)) & 0x33333333u;
  v = (v | (v << 1)) & 0x55555555u;
  return v;
}

// The boxes' indices in Morton (Z) order of their centres on a 65536 x 65536 grid over their
// bounds.
std::vector<std::size_t> mortonOrder(const std::vector<Aabb2>& boxes) {
  Aabb2 all = boxes.empty() ? Aabb2{} : boxes.front();
  for (const Aabb2& b : boxes) all = all.merged(b);
  const Eigen::Vector2d extent = (all.max - all.min).cwiseMax(Eigen::Vector2d(1e-9, 1e-9));
  std::vector<std::pair<std::uint32_t, std::size_t>> keyed(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Eigen::Vector2d c = 0.5 * (boxes[i].min + boxes[i].max);
    const auto cell = [](double t) {
      return static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 65535.0);
    };
    const std::uint32_t x = cell((c.x() - all.min.x()) / extent.x());
    const std::uint32_t y = cell((c.y() - all.min.y()) / extent.y());
    keyed[i] = {spreadBits(x) | (spreadBits(y) << 1), i};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> order(boxes.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

// Inserts every box in `order` (the order is computed beforehand and not timed).
void fillTree(b2DynamicTree& tree, const std::vector<Aabb2>& boxes,
              const std::vector<std::size_t>& order) {
  for (const std::size_t i : order) {
    // The user data is the car index, as a b2World's fixture proxy would carry its fixture.
    tree.CreateProxy(toB2(boxes[i]), reinterpret_cast<void*>(i + 1));
  }
}

// The order in which Box2D's tree gets the boxes. b2DynamicTree inserts each proxy beside its
// best sibling as it comes, so the order shapes the tree, and Box2D has no bulk build for a large
// one (RebuildBottomUp is quadratic). So each layout is inserted in a spatially coherent order, as
// a user who cares would: the lot in its own order (row by row, as the scene lists its cars), the
// random layout in Morton order (its own order is random: at 1M cars its queries took about ten
// times as long). Computed once, not timed.
const std::vector<std::size_t>& insertionOrder(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<std::vector<std::size_t>>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) {
    const std::vector<Aabb2>& boxes = lot(random, n).boxes;
    slot = std::make_unique<std::vector<std::size_t>>(boxes.size());
    if (random) {
      *slot = mortonOrder(boxes);
    } else {
      for (std::size_t i = 0; i < boxes.size(); ++i) (*slot)[i] = i;
    }
  }
  return *slot;
}

const b2DynamicTree& tree(bool random, std::size_t n) {
  static std::map<std::pair<bool, std::size_t>, std::unique_ptr<b2DynamicTree>> cache;
  auto& slot = cache[{random, n}];
  if (!slot) {
    slot = std::make_unique<b2DynamicTree>();
    fillTree(*slot, lot(random, n).boxes, insertionOrder(random, n));
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

using QueriesOf = const std::vector<Aabb2>& (*)(bool random, std::size_t n);

// The query rows `group` + engine: each iteration queries the next box of queriesOf(random, n)
// (cycled), the grid into a QueryIds as World::step does, Box2D's tree with a callback.
void registerQueries(const std::string& group, bool random, std::size_t n, QueriesOf queriesOf) {
  benchmark::RegisterBenchmark(
      (group + "cardemo").c_str(), [random, n, queriesOf](benchmark::State& s) {
        const std::vector<Aabb2>& queries = queriesOf(random, n);
        const UniformGrid& g = grid(random, n);
        QueryIds out;
        out.reserve(4096);
        std::size_t step = 0, found = 0;
        for (auto _ : s) {
          g.query(queries[step], out);
          found += out.size();
          step = (step + 1) % queries.size();
          benchmark::DoNotOptimize(out.begin());
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()));
        s.counters["candidates"] = static_cast<double>(found) /
                                   static_cast<double>(std::max<std::int64_t>(1, s.iterations()));
        s.counters["bytes_per_car"] = static_cast<double>(g.memoryBytes()) / static_cast<double>(n);
        // The base level's cell width and height (the build picks their shape, grid_cells.hpp).
        s.counters["cell_m"] = g.levelCount() > 0 ? g.cellSize(0).x() : 0.0;
        s.counters["cell_height_m"] = g.levelCount() > 0 ? g.cellSize(0).y() : 0.0;
      });
#if defined(CARDEMO_HAVE_COMPARE)
  benchmark::RegisterBenchmark(
      (group + "box2d").c_str(), [random, n, queriesOf](benchmark::State& s) {
        const std::vector<Aabb2>& queries = queriesOf(random, n);
        const b2DynamicTree& t = tree(random, n);
        std::vector<std::uint32_t> out;
        out.reserve(4096);
        TreeCollector collector{&t, &out};
        std::size_t step = 0, found = 0;
        for (auto _ : s) {
          out.clear();
          t.Query(&collector, toB2(queries[step]));
          found += out.size();
          step = (step + 1) % queries.size();
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
  registerQueries("broad/query/" + prefix, random, n, &pathOf);
#if defined(CARDEMO_HAVE_COMPARE)
  benchmark::RegisterBenchmark(
      ("broad/build/" + prefix + "box2d").c_str(), [random, n](benchmark::State& s) {
        const Lot& l = lot(random, n);
        const std::vector<std::size_t>& order = insertionOrder(random, n);
        for (auto _ : s) {
          b2DynamicTree t;
          fillTree(t, l.boxes, order);
          benchmark::DoNotOptimize(t.GetHeight());
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) *
                            static_cast<std::int64_t>(n));
        // A tree over N leaves has 2N - 1 nodes; Box2D allocates at least that many.
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
    // Queries spread over the whole world, at the largest size only (2^20 query boxes a layout).
    if (!config.smoke) {
      const std::size_t n = sizes.back();
      registerQueries(
          "broad/scattered/" + std::string(random ? "random/" : "lot/") + sizeLabel(n) + "/",
          random, n, &scatteredOf);
    }
  }
}

}  // namespace cardemo::bench
