#pragma once
/// The crash and scrape bookkeeping of the player's contacts: which colliders were touched at the
/// last frame, each collider's crash window and what its crash has charged, and the scraping.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/state_hash.hpp"

namespace cardemo {

/// What a first contact with a collider costs: its damage and the crash it belongs to.
struct CrashCharge {
  int damage = 0;          ///< Health to take: the impact's worth beyond what its crash charged.
  std::int64_t crash = 0;  ///< The crash (1, 2, ...): re-touches within the window share one.
};

/// Per-collider crash windows (a re-touch within the window of the last contact is the same crash,
/// which costs only what the new impact is worth beyond what the crash already took), the touching
/// flags of the last frame, and scrape damage counted in whole frames. Sized once; never allocates.
class CrashLedger {
 public:
  /// A ledger for `colliders` colliders whose crash window lasts `window_frames` frames.
  CrashLedger(std::size_t colliders, std::int64_t window_frames);

  /// True when collider `id` was in contact at the previous frame.
  [[nodiscard]] bool touching(std::uint32_t id) const { return touching_[id] != 0; }
  /// Sets collider `id`'s contact flag for the next frame.
  void setTouching(std::uint32_t id, bool touching) { touching_[id] = touching ? 1 : 0; }

  /// A first contact with `id` at `frame` (a hit) worth `worth` damage: within the collider's
  /// crash window it joins that crash and is charged only the excess; otherwise a new crash starts.
  CrashCharge hit(std::uint32_t id, std::int64_t frame, int worth);
  /// Contact with `id` at `frame`: its crash window now runs window_frames past it.
  void touch(std::uint32_t id, std::int64_t frame) { crash_until_[id] = frame + window_frames_; }

  /// One more frame of scraping at `damage_per_s` (whole points over all frames so far at `hz`
  /// frames a second, exact); returns the damage this frame adds.
  int scrapeFrame(double damage_per_s, double hz);

  /// Crashes so far.
  [[nodiscard]] std::int64_t crashes() const { return crash_count_; }
  /// Crashes that cost health: each counts once, from its first hit with damage.
  [[nodiscard]] std::int64_t damagingCrashes() const { return damaging_crash_count_; }
  /// Health taken by scraping so far.
  [[nodiscard]] int scrapeDamage() const { return scrape_damage_; }

  /// Feeds the state that later frames depend on at `frame` (the scrape count and damage, the
  /// crash count, the crash windows still open in collider order) to `h`.
  void hashInto(Fnv1a64& h, std::int64_t frame) const;

 private:
  std::vector<std::uint8_t> touching_;     // per collider: in contact at the previous frame
  std::vector<std::int64_t> crash_until_;  // per collider: last frame of its crash window, or -1
  std::vector<int> crash_charged_;         // per collider: damage its crash has charged so far
  std::vector<std::int64_t> crash_of_;     // per collider: its crash's number
  std::int64_t window_frames_ = 0;
  std::int64_t crash_count_ = 0;
  std::int64_t damaging_crash_count_ = 0;
  std::int64_t scrape_frames_ = 0;  // frames spent scraping so far
  int scrape_damage_ = 0;           // damage charged for them
};

}  // namespace cardemo
