#include "sim/crash_ledger.hpp"

#include <algorithm>
#include <cmath>

namespace cardemo {

CrashLedger::CrashLedger(std::size_t colliders, std::int64_t window_frames)
    : touching_(colliders, 0),
      crash_until_(colliders, -1),
      crash_charged_(colliders, 0),
      crash_of_(colliders, 0),
      window_frames_(window_frames) {}

CrashCharge CrashLedger::hit(std::uint32_t id, std::int64_t frame, int worth) {
  int damage = worth;
  // A crash has cost health once anything is charged to it.
  bool charged_before = false;
  if (frame <= crash_until_[id]) {
    charged_before = crash_charged_[id] > 0;
    damage = std::max(0, worth - crash_charged_[id]);
    crash_charged_[id] += damage;
  } else {
    crash_of_[id] = ++crash_count_;
    crash_charged_[id] = worth;
  }
  if (damage > 0 && !charged_before) ++damaging_crash_count_;
  return {damage, crash_of_[id]};
}

int CrashLedger::scrapeFrame(double damage_per_s, double hz) {
  // Damage by time, counted in whole frames so that it is exact: floor(frames * rate / hz) in all.
  ++scrape_frames_;
  const int due = static_cast<int>(
      std::min(std::floor(static_cast<double>(scrape_frames_) * damage_per_s / hz), 1e9));
  const int added = due - scrape_damage_;
  scrape_damage_ = due;
  return added;
}

void CrashLedger::hashInto(Fnv1a64& h, std::int64_t frame) const {
  h.addInt(scrape_frames_);
  h.addInt(scrape_damage_);
  h.addInt(crash_count_);
  // The crash windows still open (a later re-touch depends on them), in collider order.
  for (std::size_t i = 0; i < crash_until_.size(); ++i) {
    if (crash_until_[i] < frame) continue;
    h.add(static_cast<std::uint64_t>(i));
    h.addInt(crash_until_[i]);
    h.addInt(crash_charged_[i]);
    h.addInt(crash_of_[i]);
  }
}

}  // namespace cardemo
