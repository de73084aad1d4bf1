#pragma once
/// One pair judged every way the comparison knows: ours, the exact oracle and Box2D 2.4.1.

#include <array>
#include <cstdint>

#include "collision/narrow_phase.hpp"
#include "compare/box2d/box2d_shapes.hpp"
#include "sim/walls.hpp"

namespace cardemo::compare {

/// Each verdict the comparison records. The exact oracle is the reference the others are held to.
enum class Verdict : int {
  kOurs = 0,          ///< cardemo: collidePlayer(...).separation <= 0.
  kBox2d,             ///< b2CollidePolygons with skin 0: pointCount > 0 (the contract's `box2d`).
  kBox2dOverlap,      ///< b2TestOverlap with skin 0.
  kBox2dSkin,         ///< b2CollidePolygons with the default 0.01 m skin.
  kBox2dSkinOverlap,  ///< b2TestOverlap with the default 0.01 m skin.
  kExact,             ///< GMP oracle (or the double SAT when it is far from touching, see below).
};

/// Number of Verdict values.
inline constexpr int kVerdictCount = 6;

/// JSON key / table label of a verdict.
[[nodiscard]] const char* verdictKey(Verdict v);

/// The contract's tolerance: a pair with |exact separation| <= this is "borderline", metres.
inline constexpr double kBorderline = 1e-6;

/// Beyond this |double SAT separation| the exact verdict is taken from the double SAT without GMP.
/// Sound because our separation is within 2e-6 m of the exact one (CONTRACT.md accuracy, checked
/// against the oracle in tests/exact), 500 times below this threshold.
inline constexpr double kExactShortcut = 1e-3;

/// Box2D's shapes for one side of a pair, with and without the default skin.
struct Box2dPair {
  Box2dShape bare;  ///< Skin 0.
  Box2dShape skin;  ///< Skin kBox2dDefaultSkin.
};

/// Box2D shapes of a static collider (box or obstacle), built once.
[[nodiscard]] Box2dPair box2dShapesOf(const StaticShape& shape);

/// All verdicts for one pair.
struct PairVerdicts {
  std::array<bool, kVerdictCount> hit{};  ///< Indexed by Verdict.
  double exact_separation = 0.0;          ///< Exact (or shortcut double) separation, metres.
  double ours_separation = 0.0;           ///< cardemo's double separation, metres.
  bool used_gmp = false;                  ///< True when the GMP oracle ran.
};

/// Judges the player box against a static shape every way. `player_b2` must be at `player`'s pose.
/// `all_exact` forces the GMP oracle even far from touching.
[[nodiscard]] PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2,
                                     const StaticShape& shape, const Box2dPair& shape_b2,
                                     bool all_exact);
/// judgePair against a parked car's box.
[[nodiscard]] PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2,
                                     const Obb2& box, const Box2dPair& shape_b2, bool all_exact);
/// judgePair against an obstacle.
[[nodiscard]] PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2,
                                     const ConvexPolygon& polygon, const Box2dPair& shape_b2,
                                     bool all_exact);

/// Box2D's edges for one wall, with and without the default skin.
struct Box2dWall {
  Box2dEdge bare;  ///< Skin 0.
  Box2dEdge skin;  ///< Skin kBox2dDefaultSkin.
};

/// Box2D's two-sided edge along one wall of `walls` (the whole side of the bounds).
[[nodiscard]] Box2dWall box2dWallOf(const Aabb2& walls, WallSide side);

/// Judges the player box against one wall of the scene's bounds every way: ours is the World's own
/// test (the box's bounds reach the wall: wallDepths >= 0), exact the oracle's (collideObbWall),
/// Box2D a two-sided edge against the box.
[[nodiscard]] PairVerdicts judgeWall(const Obb2& player, const Box2dPair& player_b2,
                                     const Aabb2& walls, WallSide side, const Box2dWall& wall_b2,
                                     bool all_exact);

/// Agreement of one verdict with the exact one.
enum class Agreement { kAgree, kDisagree, kBorderline };

/// kAgree when equal; otherwise kBorderline when |exact_separation| <= kBorderline, else kDisagree.
[[nodiscard]] Agreement agreementOf(bool verdict, bool exact, double exact_separation);

}  // namespace cardemo::compare
