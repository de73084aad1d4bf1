#include "play/sound_mix.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cardemo {

std::array<double, kEngineLoops> engineGains(double speed, const SoundSettings& settings) {
  std::array<double, kEngineLoops> gains{};
  const double t = std::clamp(std::abs(speed) / settings.top_speed, 0.0, 1.0);
  const double position = t * static_cast<double>(kEngineLoops - 1);
  const auto low = std::min(static_cast<std::size_t>(position), kEngineLoops - 2);
  const double w = position - static_cast<double>(low);
  // Equal-power cross-fade: cos^2 + sin^2 = 1 at every point of the fade.
  gains[low] = std::cos(w * std::numbers::pi / 2.0);
  gains[low + 1] = std::sin(w * std::numbers::pi / 2.0);
  return gains;
}

double screechLevel(const CarState& car, const CarParams& params, const InputFrame& input,
                    const SoundSettings& settings) {
  const double lateral = car.speed * car.speed * std::abs(std::tan(car.steer)) / params.wheelbase;
  double level = std::clamp(
      (lateral - settings.slide_accel) / (settings.slide_full_accel - settings.slide_accel), 0.0,
      1.0);
  if (input.down && car.speed > settings.brake_screech_speed) {
    level = std::max(level, std::min(1.0, car.speed / (4.0 * settings.brake_screech_speed) + 0.5));
  }
  return level;
}

SoundFrame SoundMix::update(const World& world, const InputFrame& input, bool holding) {
  SoundFrame out;
  const std::vector<HitEvent>& hits = world.hits();
  // A restarted game starts with fewer hits, or at an earlier frame.
  if (hits.size() < hits_heard_ || world.frame() < last_frame_) hits_heard_ = 0;
  last_frame_ = world.frame();
  int damage = -1;
  for (std::size_t i = hits_heard_; i < hits.size(); ++i) damage = std::max(damage, hits[i].damage);
  hits_heard_ = hits.size();
  if (damage >= 0) {
    out.impact = std::clamp(static_cast<double>(damage) / settings_.full_impact_damage,
                            settings_.min_impact_level, 1.0);
  }
  if (holding || world.gameOver()) return out;
  const double speed = world.car().speed;
  const double level =
      std::min(1.0, settings_.idle_level +
                        (1.0 - settings_.idle_level - settings_.throttle_level) *
                            std::clamp(std::abs(speed) / settings_.top_speed, 0.0, 1.0) +
                        (input.up || input.down ? settings_.throttle_level : 0.0));
  out.engine = engineGains(speed, settings_);
  for (double& g : out.engine) g *= level;
  out.screech = screechLevel(world.car(), world.settings().car, input, settings_);
  if (world.sliding()) {
    // The simulation's own verdict (slip over CarParams::skid_slip, or the handbrake locking
    // moving wheels): at least a clear squeal, louder with the slip speed.
    out.screech =
        std::max(out.screech, std::clamp(std::abs(world.slipSpeed()) / settings_.full_screech_slip,
                                         settings_.min_slide_level, 1.0));
  }
  return out;
}

}  // namespace cardemo
