#pragma once
/// Each file of the suite registers its benchmarks here (sizes depend on the smoke setting).
///
/// Names are `group/query/size/engine`; rows that differ only in the engine (`cardemo`, `avx2`,
/// `portable`, `box2d`) measure the same work on the same data, and scripts/perf_report.py
/// prints their ratio.

#include <string>

#include "bench_data.hpp"

namespace cardemo::bench {

/// Narrow phase: scalar pair queries, cardemo and Box2D, on 1k and 1M random pairs.
void registerNarrow(const BenchConfig& config);
/// Batch kernels: one box against many, both dispatch paths, with Box2D and scalar references.
void registerBatch(const BenchConfig& config);
/// Broad phase: UniformGrid and b2DynamicTree, build and query over parked cars.
void registerBroad(const BenchConfig& config);
/// Whole step: World::step and b2World::Step with one car among N parked cars; World::step on
/// the circling replay of scripts/replay_speed.py.
void registerStep(const BenchConfig& config);
/// Cost per pair at 0, 1e3, 1e5 and 1e7 m from the origin, cardemo and Box2D.
void registerOffset(const BenchConfig& config);
/// Loading a large scene, and headless replay speed on the bundled lot.
void registerLoad(const BenchConfig& config);

/// "1k", "1M", "100", ... for benchmark names.
[[nodiscard]] std::string sizeLabel(std::size_t n);

}  // namespace cardemo::bench
