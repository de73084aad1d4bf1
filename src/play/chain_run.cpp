#include "play/chain_run.hpp"

#include <utility>

namespace cardemo {

ChainRun::ChainRun(const World& world, std::string best_path, bool keeps_best)
    : best_path_(std::move(best_path)), keeps_best_(keeps_best) {
  const Scene& scene = world.scene();
  scene_name_ = scene.name;
  // A level has its own goal; a lot with no free bay is plain free drive.
  has_bays_ = !scene.goal && !findFreeBays(scene).empty();
  if (has_bays_ && !best_path_.empty()) scores_ = loadBestScores(best_path_, warning_);
  restart(world);
}

void ChainRun::restart(const World& world) {
  chain_.reset();
  new_best_ = false;
  best_before_.reset();
  if (!has_bays_) return;
  if (const ChainScore* best = scores_.findChain(scene_name_)) best_before_ = *best;
  chain_.emplace(world.scene(), world.settings().hz);
  chain_->observe(world);
  if (chain_->over()) finish();
}

bool ChainRun::observe(const World& world) {
  if (!chain_ || chain_->over()) return false;
  chain_->observe(world);
  if (!chain_->over()) return false;
  finish();
  return true;
}

void ChainRun::finish() {
  const ChainScore score = chain_->score();
  // No bay parked is no score to keep ("none yet" stays).
  if (!keeps_best_ || score.count == 0) return;
  if (scores_.offerChain(scene_name_, score)) {
    new_best_ = true;
    if (!best_path_.empty()) {
      if (std::string why = saveBestScores(best_path_, scores_); !why.empty()) {
        warning_ = "best score not saved: " + why;
      }
    }
  }
}

std::string ChainRun::takeWarning() {
  return std::exchange(warning_, std::string());
}

}  // namespace cardemo
