#include "play/level_run.hpp"

#include <utility>

namespace cardemo {

LevelRun::LevelRun(const World& world, std::string best_path, bool keeps_best)
    : best_path_(std::move(best_path)), keeps_best_(keeps_best) {
  scene_name_ = world.scene().name;
  if (world.scene().goal && !best_path_.empty()) scores_ = loadBestScores(best_path_, warning_);
  restart(world);
}

void LevelRun::restart(const World& world) {
  challenge_.reset();
  new_best_ = false;
  best_before_.reset();
  const Scene& scene = world.scene();
  if (!scene.goal) return;
  if (const ParkingScore* best = scores_.find(scene_name_)) best_before_ = *best;
  challenge_.emplace(*scene.goal, world.settings().hz, scene.player.health);
  challenge_->observe(world);
  if (challenge_->over()) finish();
}

bool LevelRun::observe(const World& world) {
  if (!challenge_ || challenge_->over()) return false;
  challenge_->observe(world);
  if (!challenge_->over()) return false;
  finish();
  return true;
}

void LevelRun::finish() {
  if (!keeps_best_) return;
  if (const std::optional<ParkingScore> score = challenge_->score()) {
    if (scores_.offer(scene_name_, *score)) {
      new_best_ = true;
      if (!best_path_.empty()) {
        if (std::string why = saveBestScores(best_path_, scores_); !why.empty()) {
          warning_ = "best score not saved: " + why;
        }
      }
    }
  }
}

std::string LevelRun::takeWarning() {
  return std::exchange(warning_, std::string());
}

}  // namespace cardemo
