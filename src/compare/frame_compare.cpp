// Frame-by-frame comparison of cardemo, the exact oracle and Box2D on a running World.

#include "compare/frame_compare.hpp"

#include <algorithm>
#include <cmath>

namespace cardemo::compare {
namespace {

// Euclidean distance between two AABBs (0 when they overlap).
double aabbDistance(const Aabb2& a, const Aabb2& b) {
  const double dx = std::max({0.0, b.min.x() - a.max.x(), a.min.x() - b.max.x()});
  const double dy = std::max({0.0, b.min.y() - a.max.y(), a.min.y() - b.max.y()});
  return std::hypot(dx, dy);
}

}  // namespace

FrameComparer::FrameComparer(const World& world, const CompareOptions& options)
    : options_(options) {
  report_.radius = options.radius;
  const StaticColliders& colliders = world.colliders();
  shapes_.reserve(colliders.size());
  report_.ids.reserve(colliders.size());
  for (std::uint32_t i = 0; i < colliders.size(); ++i) {
    shapes_.push_back(box2dShapesOf(colliders.shape(i)));
    report_.ids.push_back(world.colliderId(i));
  }
  if (const std::optional<Aabb2>& bounds = world.scene().bounds) {
    for (const WallSide side : kWallSides) {
      walls_.push_back(box2dWallOf(*bounds, side));
      report_.ids.push_back(wallId(side));
    }
  }
  for (auto& last : last_true_) last.assign(report_.ids.size(), -2);
  player_ = box2dShapesOf(world.carBox());
  check(world);
}

void FrameComparer::check(const World& world) {
  const Obb2 player = world.carBox();
  setBox2dPose(player_.bare, player);
  setBox2dPose(player_.skin, player);
  const Aabb2 player_bounds = player.aabb();
  const StaticColliders& colliders = world.colliders();
  report_.frames = world.frame();
  for (std::uint32_t i = 0; i < colliders.size(); ++i) {
    if (options_.radius && aabbDistance(player_bounds, colliders.bounds(i)) > *options_.radius)
      continue;
    const PairVerdicts v = colliders.visit(i, [&](const auto& shape) {
      return judgePair(player, player_, shape, shapes_[i], options_.all_exact);
    });
    record(world.frame(), i, v);
  }
  if (walls_.empty()) return;
  const Aabb2& bounds = *world.scene().bounds;
  const std::array<double, kWallCount> depth = wallDepths(player_bounds, bounds);
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    if (options_.radius && -depth[k] > *options_.radius) continue;
    const PairVerdicts v =
        judgeWall(player, player_, bounds, kWallSides[k], walls_[k], options_.all_exact);
    record(world.frame(), static_cast<std::uint32_t>(colliders.size() + k), v);
  }
}

void FrameComparer::record(std::int64_t frame, std::uint32_t collider, const PairVerdicts& v) {
  ++report_.pairs_checked;
  if (v.used_gmp) ++report_.gmp_calls;
  const bool exact = v.hit[static_cast<std::size_t>(Verdict::kExact)];
  for (std::size_t k = 0; k < kVerdictCount; ++k) {
    VerdictRecord& r = report_.verdicts[k];
    const bool said = v.hit[k];
    switch (agreementOf(said, exact, v.exact_separation)) {
      case Agreement::kAgree:
        ++r.tally.agree;
        break;
      case Agreement::kBorderline:
        ++r.tally.borderline;
        if (r.borderline_pairs.size() < kMaxBorderline)
          r.borderline_pairs.push_back({frame, collider, said, v.exact_separation});
        break;
      case Agreement::kDisagree:
        ++r.tally.disagree;
        if (r.examples.size() < options_.max_examples)
          r.examples.push_back({frame, collider, said, v.exact_separation});
        break;
    }
    if (said) {
      std::int64_t& last = last_true_[k][collider];
      if (last != frame - 1) r.hits.push_back({frame, collider});
      last = frame;
    }
  }
}

int compareExitStatus(const CompareReport& report) {
  return report[Verdict::kOurs].tally.disagree > 0 ? 1 : 0;
}

}  // namespace cardemo::compare
