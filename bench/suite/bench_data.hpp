#pragma once
/// Seeded data for the benchmark suite: pair sets, parking lots, query paths, scenes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "sim/scene.hpp"

namespace cardemo::bench {

/// Numerical Recipes' 32-bit LCG, the generator of scripts/make_large_lot.py and
/// scripts/replay_speed.py, so C++ and Python build the same scenes.
class Lcg {
 public:
  /// Starts from `seed`.
  explicit Lcg(std::uint32_t seed) : state_(seed) {}
  /// Next value in [0, 1).
  double uniform() {
    state_ = 1664525u * state_ + 1013904223u;
    return static_cast<double>(state_) / 4294967296.0;
  }

 private:
  std::uint32_t state_;
};

/// Suite-wide settings: the smoke run (CTest) uses small sizes and no timing claims.
struct BenchConfig {
  bool smoke = false;  ///< Small N everywhere; only checks that every benchmark runs.
};

/// Independent 2D pairs (a[i], b[i]) of car-sized boxes, in random order, with the share that
/// touches or overlaps close to `overlap_target`.
struct PairSet2 {
  std::vector<Obb2> a;         ///< First boxes.
  std::vector<Obb2> b;         ///< Second boxes.
  double overlap_share = 0.0;  ///< Measured share of overlapping pairs.
};

/// 3D pairs of box-shaped bodies (cars, crates), random rotations.
struct PairSet3 {
  std::vector<Obb3> a;         ///< First boxes.
  std::vector<Obb3> b;         ///< Second boxes.
  double overlap_share = 0.0;  ///< Measured share of overlapping pairs.
};

/// `n` 2D pairs, about 45% overlapping. Deterministic for a given n.
[[nodiscard]] const PairSet2& pairSet2(std::size_t n);
/// One query box and `n` boxes around it, about 45% of them overlapping it; a tenth of the boxes,
/// picked at random, are within 1e-5 m of touching it (either side).
[[nodiscard]] const PairSet2& batchSet2(std::size_t n);
/// `n` 3D pairs, about 45% overlapping.
[[nodiscard]] const PairSet3& pairSet3(std::size_t n);
/// One 3D query box and `n` boxes around it, about 45% of them overlapping it.
[[nodiscard]] const PairSet3& batchSet3(std::size_t n);

/// A parked car of a generated lot.
struct LotCar {
  Obb2 box;                  ///< World box.
  double heading_deg = 0.0;  ///< Heading as a scene file would state it.
};

/// `n` parked cars in double rows of 104 bays with aisles, as scripts/make_large_lot.py lays out
/// the bundled large lot (same pitch, jitter and 3% empty bays), as many blocks as needed.
[[nodiscard]] std::vector<LotCar> lotLayout(std::size_t n);
/// `n` cars at random places and headings, at the lot's density (one car per 21 m^2).
[[nodiscard]] std::vector<LotCar> randomLayout(std::size_t n);
/// Tight AABBs of the cars.
[[nodiscard]] std::vector<Aabb2> boundsOf(const std::vector<LotCar>& cars);
/// Car-sized query boxes (AABB of a 4.5 x 1.8 m car, turning) moving in 0.25 m steps through
/// the bounds of `boxes`, crossing aisles and rows.
[[nodiscard]] std::vector<Aabb2> queryPath(const std::vector<Aabb2>& boxes, std::size_t steps);
/// `count` car-sized query boxes (AABB of a 4.5 x 1.8 m car) at uniformly random places and
/// headings over the bounds of `boxes`, each independent of the one before (seeded).
[[nodiscard]] std::vector<Aabb2> scatteredQueries(const std::vector<Aabb2>& boxes,
                                                  std::size_t count);

/// A scene of `n` parked cars in the lot layout; the player waits at the west end of the middle
/// aisle, facing east, with the most health a scene may give (no game over in the drives).
[[nodiscard]] Scene lotScene(std::size_t n);
/// The same scene as scene JSON text (cardemo-scene/1), ids like "00N-001".
[[nodiscard]] std::string lotSceneJson(std::size_t n);

}  // namespace cardemo::bench
