// One pair judged by cardemo, the exact oracle and Box2D (two skins, two queries).

#include "compare/pair_verdicts.hpp"

#include <cmath>

#include "compare/exact/exact_sat.hpp"

namespace cardemo::compare {

const char* verdictKey(Verdict v) {
  switch (v) {
    case Verdict::kOurs:
      return "ours";
    case Verdict::kBox2d:
      return "box2d";
    case Verdict::kBox2dOverlap:
      return "box2d_overlap";
    case Verdict::kBox2dSkin:
      return "box2d_skin";
    case Verdict::kBox2dSkinOverlap:
      return "box2d_skin_overlap";
    case Verdict::kExact:
      return "exact";
  }
  return "?";
}

Box2dPair box2dShapesOf(const StaticShape& shape) {
  if (const Obb2* box = std::get_if<Obb2>(&shape)) {
    return {box2dBox(*box, 0.0f), box2dBox(*box, kBox2dDefaultSkin)};
  }
  const ConvexPolygon& polygon = std::get<ConvexPolygon>(shape);
  return {box2dPolygon(polygon, 0.0f), box2dPolygon(polygon, kBox2dDefaultSkin)};
}

namespace {

exact::ExactResult exactCollide(const Obb2& player, const Obb2& box) {
  return exact::collideObb2(player, box);
}

exact::ExactResult exactCollide(const Obb2& player, const ConvexPolygon& polygon) {
  return exact::collideObbPolygon(player, polygon);
}

template <class Shape>
PairVerdicts judgeShape(const Obb2& player, const Box2dPair& player_b2, const Shape& shape,
                        const Box2dPair& shape_b2, bool all_exact) {
  PairVerdicts out;
  const double ours = collidePlayer(player, shape).separation;
  out.hit[static_cast<int>(Verdict::kOurs)] = ours <= 0.0;
  out.ours_separation = ours;
  if (!all_exact && std::abs(ours) > kExactShortcut) {
    out.exact_separation = ours;
    out.hit[static_cast<int>(Verdict::kExact)] = ours <= 0.0;
  } else {
    const exact::ExactResult e = exactCollide(player, shape);
    out.exact_separation = e.separation;
    out.hit[static_cast<int>(Verdict::kExact)] = e.hit;
    out.used_gmp = true;
  }
  const Box2dVerdict bare = box2dCollide(player_b2.bare, shape_b2.bare);
  const Box2dVerdict skin = box2dCollide(player_b2.skin, shape_b2.skin);
  out.hit[static_cast<int>(Verdict::kBox2d)] = bare.points > 0;
  out.hit[static_cast<int>(Verdict::kBox2dOverlap)] = bare.overlap;
  out.hit[static_cast<int>(Verdict::kBox2dSkin)] = skin.points > 0;
  out.hit[static_cast<int>(Verdict::kBox2dSkinOverlap)] = skin.overlap;
  return out;
}

}  // namespace

PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2, const Obb2& box,
                       const Box2dPair& shape_b2, bool all_exact) {
  return judgeShape(player, player_b2, box, shape_b2, all_exact);
}

PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2, const ConvexPolygon& polygon,
                       const Box2dPair& shape_b2, bool all_exact) {
  return judgeShape(player, player_b2, polygon, shape_b2, all_exact);
}

PairVerdicts judgePair(const Obb2& player, const Box2dPair& player_b2, const StaticShape& shape,
                       const Box2dPair& shape_b2, bool all_exact) {
  return std::visit(
      [&](const auto& s) { return judgePair(player, player_b2, s, shape_b2, all_exact); }, shape);
}

Box2dWall box2dWallOf(const Aabb2& walls, WallSide side) {
  const Eigen::Vector2d sw = walls.min, ne = walls.max;
  const Eigen::Vector2d se(ne.x(), sw.y()), nw(sw.x(), ne.y());
  Eigen::Vector2d a = sw, b = nw;
  switch (side) {
    case WallSide::kWest:
      break;
    case WallSide::kEast:
      a = se;
      b = ne;
      break;
    case WallSide::kSouth:
      b = se;
      break;
    case WallSide::kNorth:
      a = nw;
      b = ne;
      break;
  }
  return {box2dEdge(a, b, 0.0f), box2dEdge(a, b, kBox2dDefaultSkin)};
}

PairVerdicts judgeWall(const Obb2& player, const Box2dPair& player_b2, const Aabb2& walls,
                       WallSide side, const Box2dWall& wall_b2, bool all_exact) {
  PairVerdicts out;
  const double ours = -wallDepths(player.aabb(), walls)[static_cast<std::size_t>(side)];
  out.hit[static_cast<int>(Verdict::kOurs)] = ours <= 0.0;
  out.ours_separation = ours;
  if (!all_exact && std::abs(ours) > kExactShortcut) {
    out.exact_separation = ours;
    out.hit[static_cast<int>(Verdict::kExact)] = ours <= 0.0;
  } else {
    const exact::ExactResult e = exact::collideObbWall(player, walls, side);
    out.exact_separation = e.separation;
    out.hit[static_cast<int>(Verdict::kExact)] = e.hit;
    out.used_gmp = true;
  }
  const Box2dVerdict bare = box2dCollide(player_b2.bare, wall_b2.bare);
  const Box2dVerdict skin = box2dCollide(player_b2.skin, wall_b2.skin);
  out.hit[static_cast<int>(Verdict::kBox2d)] = bare.points > 0;
  out.hit[static_cast<int>(Verdict::kBox2dOverlap)] = bare.overlap;
  out.hit[static_cast<int>(Verdict::kBox2dSkin)] = skin.points > 0;
  out.hit[static_cast<int>(Verdict::kBox2dSkinOverlap)] = skin.overlap;
  return out;
}

Agreement agreementOf(bool verdict, bool exact, double exact_separation) {
  if (verdict == exact) return Agreement::kAgree;
  return std::abs(exact_separation) <= kBorderline ? Agreement::kBorderline : Agreement::kDisagree;
}

}  // namespace cardemo::compare
