#include "render/effects.hpp"

#include <algorithm>
#include <cmath>

namespace cardemo {
namespace {

constexpr std::int64_t kLongAgo = -1'000'000;
constexpr std::size_t kMaxNumbers = 16;
// Tyre centres sit this far inside the body's side, metres.
constexpr double kTyreInset = 0.28;

// splitmix64 (Steele, Lea, Flood 2014): a well-mixed integer from a counter, no state.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A number in [-1, 1] from the top bits of a hash.
double unit(std::uint64_t h) {
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

// Support distance of `box` along unit direction n (from its centre to its boundary along n).
double support(const Obb2& box, const Eigen::Vector2d& n) {
  return std::abs(n.dot(box.axis)) * box.half.x() + std::abs(n.dot(box.perp())) * box.half.y();
}

// `world_point` in the box's frame, moved onto the nearest side of the box.
Eigen::Vector2d onBoundary(const Obb2& box, const Eigen::Vector2d& world_point) {
  const Eigen::Vector2d d = world_point - box.center;
  Eigen::Vector2d local{d.dot(box.axis), d.dot(box.perp())};
  local = local.cwiseMax(-box.half).cwiseMin(box.half);
  // Snap to whichever side is closest, so the dent sits on the body's edge.
  const double gx = box.half.x() - std::abs(local.x());
  const double gy = box.half.y() - std::abs(local.y());
  if (gx < gy) {
    local.x() = std::copysign(box.half.x(), local.x());
  } else {
    local.y() = std::copysign(box.half.y(), local.y());
  }
  return local;
}

}  // namespace

std::array<Eigen::Vector2d, 4> tyrePositions(const Obb2& box, double wheelbase) {
  const double ax = std::min(0.5 * wheelbase, 0.8 * box.half.x());
  const double ay = std::max(0.0, box.half.y() - kTyreInset);
  const Eigen::Vector2d f = box.axis * ax;
  const Eigen::Vector2d s = box.perp() * ay;
  return {box.center + f + s, box.center + f - s, box.center - f + s, box.center - f - s};
}

Effects::Effects(const World& world, const EffectsSettings& settings) : settings_(settings) {
  skids_.resize(std::max<std::size_t>(1, settings_.max_skid_segments));
  numbers_.reserve(kMaxNumbers);
  dents_.reserve(settings_.max_dents);
  reset(world);
}

void Effects::reset(const World& world) {
  frame_ = world.frame();
  seen_hits_ = 0;
  player_flash_ = pulse_ = shake_start_ = kLongAgo;
  shake_px_ = 0.0;
  health_before_ = world.scene().player.health;
  collider_flash_.assign(world.colliders().size(), kLongAgo);
  skid_head_ = skid_count_ = 0;
  laying_.fill(false);
  open_count_ = 0;
  numbers_.clear();
  dents_.clear();
  last_speed_ = world.car().speed;
  braking_ = marking_ = false;
  reversing_ = world.car().speed < -0.05;
  observe(world);
}

void Effects::idle(int frames) {
  if (frames > 0) frame_ += frames;
}

float Effects::fade(std::int64_t start, int frames) const {
  const std::int64_t age = frame_ - start;
  if (frames <= 0 || age < 0 || age >= frames) return 0.0f;
  return 1.0f - static_cast<float>(age) / static_cast<float>(frames);
}

float Effects::colliderFlash(std::uint32_t index) const {
  if (index >= collider_flash_.size()) return 0.0f;
  return fade(collider_flash_[index], settings_.flash_frames);
}

Eigen::Vector2f Effects::shake() const {
  const float f = fade(shake_start_, settings_.shake_frames);
  if (f <= 0.0f) return Eigen::Vector2f::Zero();
  // Amplitude decays quadratically; the direction jumps every frame, seeded by the frame only.
  const double amp = shake_px_ * static_cast<double>(f) * static_cast<double>(f);
  const std::uint64_t h = mix(static_cast<std::uint64_t>(frame_));
  return {static_cast<float>(amp * unit(h)), static_cast<float>(amp * unit(mix(h)))};
}

const SkidSegment& Effects::skid(std::size_t i) const {
  return skids_[(skid_head_ + i) % skids_.size()];
}

void Effects::pushSkid(const SkidSegment& s) {
  if (skid_count_ < skids_.size()) {
    skids_[(skid_head_ + skid_count_) % skids_.size()] = s;
    ++skid_count_;
  } else {
    skids_[skid_head_] = s;
    skid_head_ = (skid_head_ + 1) % skids_.size();
  }
}

void Effects::observe(const World& world) {
  frame_ = world.frame();
  if (collider_flash_.size() != world.colliders().size()) {
    collider_flash_.assign(world.colliders().size(), kLongAgo);
  }
  const auto& hits = world.hits();
  if (hits.size() < seen_hits_) seen_hits_ = 0;  // a different world: take its hits afresh
  for (; seen_hits_ < hits.size(); ++seen_hits_) takeHit(world, hits[seen_hits_]);
  // Numbers that have finished floating go, keeping the order of the rest.
  std::erase_if(numbers_, [this](const DamageNumber& n) {
    return frame_ - n.frame >= settings_.number_frames;
  });
  trackMotion(world);
}

void Effects::takeHit(const World& world, const HitEvent& hit) {
  if (hit.collider < collider_flash_.size()) collider_flash_[hit.collider] = hit.frame;
  player_flash_ = hit.frame;
  // A touch that costs nothing (below the damage threshold, or a bounce inside a crash already
  // charged) shows as contact only: a "-0", a dent and a pulsing bar would say it did harm.
  if (hit.damage <= 0) return;
  // A new hit restarts the shake with whichever amplitude is larger: the fresh one or what is
  // left of the last.
  const float left = fade(shake_start_, settings_.shake_frames);
  const double amp = std::min(settings_.max_shake_px, hit.damage * settings_.shake_px_per_damage);
  shake_px_ = std::max(amp, shake_px_ * static_cast<double>(left * left));
  shake_start_ = hit.frame;
  // The pulse shows what this hit took: health now plus this hit's damage (later hits in the
  // same step are added in turn).
  health_before_ = pulse_ == hit.frame ? health_before_ : world.health();
  health_before_ = std::min(world.scene().player.health, health_before_ + hit.damage);
  pulse_ = hit.frame;

  // Point of impact: where the contact normal leaves the player's box, or, without a contact
  // (the car has already bounced clear), the side facing the collider.
  const Obb2 player = world.carBox();
  Eigen::Vector2d n = Eigen::Vector2d::Zero();
  for (const ActiveContact& c : world.contacts()) {
    if (c.collider == hit.collider) n = c.normal;
  }
  const StaticColliders& colliders = world.colliders();
  const bool known = hit.collider < colliders.size();
  if (n.isZero() && known) {
    const Aabb2& b = colliders.bounds(hit.collider);
    const Eigen::Vector2d d = 0.5 * (b.min + b.max) - player.center;
    if (d.norm() > 1e-9) n = d.normalized();
  }
  if (n.isZero()) n = player.axis;
  const Eigen::Vector2d at = player.center + n * support(player, n);

  if (numbers_.size() == kMaxNumbers) numbers_.erase(numbers_.begin());
  numbers_.push_back({at, hit.damage, hit.frame});

  const double radius = 0.22 + 0.012 * std::clamp(hit.damage, 0, 50);
  const auto seed =
      static_cast<std::uint32_t>(mix(static_cast<std::uint64_t>(hit.frame) * 31u + hit.collider));
  auto addDent = [this](const Dent& d) {
    if (settings_.max_dents == 0) return;
    if (dents_.size() == settings_.max_dents) dents_.erase(dents_.begin());
    dents_.push_back(d);
  };
  addDent({kPlayerDent, onBoundary(player, at), radius, seed});
  if (known && colliders.isBox(hit.collider)) {
    addDent(
        {hit.collider, onBoundary(colliders.box(hit.collider), at), radius, seed ^ 0x5bd1e995u});
  }
}

void Effects::trackMotion(const World& world) {
  const CarState& car = world.car();
  const double hz = world.settings().hz;
  const double v = car.speed;
  // Rate at which |speed| fell over the last step; positive when slowing down.
  const double decel = (std::abs(last_speed_) - std::abs(v)) * hz;
  last_speed_ = v;
  reversing_ = world.reversing();
  braking_ = world.braking();
  // Marks where the simulation says the tyres slide (grip limit, slip, handbrake): the rear
  // tyres; braking from speed, or a stop harder than the brakes give (an impact): all four.
  const double wheelbase = world.settings().car.wheelbase;
  const bool fast = std::abs(v) > settings_.mark_min_speed;
  const bool sliding = world.sliding();
  const bool stopping = fast && (decel > settings_.hard_brake_decel ||
                                 (braking_ && std::abs(v) > settings_.brake_mark_speed));
  marking_ = sliding || stopping;

  const auto tyres = tyrePositions(world.carBox(), wheelbase);
  const float strength = static_cast<float>(std::clamp(
      std::max(std::abs(world.slipSpeed()) / 2.0, decel / (1.6 * settings_.hard_brake_decel)), 0.35,
      1.0));
  open_count_ = 0;
  for (std::size_t i = 0; i < tyres.size(); ++i) {
    // Sliding marks come from the rear tyres (they break away, or the handbrake locks them); a
    // hard stop marks all four.
    const bool lay = stopping || (sliding && i >= 2);
    if (!lay) {
      if (laying_[i] && (tyres[i] - anchor_[i]).norm() > 1e-3) {
        pushSkid({anchor_[i], tyres[i], strength});
      }
      laying_[i] = false;
      continue;
    }
    if (!laying_[i]) {
      laying_[i] = true;
      anchor_[i] = tyres[i];
    } else if ((tyres[i] - anchor_[i]).norm() >= settings_.skid_segment_m) {
      pushSkid({anchor_[i], tyres[i], strength});
      anchor_[i] = tyres[i];
    }
    open_[static_cast<std::size_t>(open_count_++)] = {anchor_[i], tyres[i], strength};
  }
}

}  // namespace cardemo
