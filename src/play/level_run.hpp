#pragma once
/// A level being played: its parking challenge beside the session's World, and the best score
/// kept in the user's data folder (saved when the car parks with a better score).

#include <optional>
#include <string>

#include "play/best_scores.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// The challenge of the scene being played (nothing when the scene has no goal).
class LevelRun {
 public:
  /// Starts on `world`'s frame (which may already park the car); `best_path` is the best-scores
  /// file (empty: scores not kept). With `keeps_best` false (a replay being watched) the stored
  /// best is shown but no run is ever offered to it or saved.
  LevelRun(const World& world, std::string best_path, bool keeps_best = true);

  /// A fresh challenge for a restarted world (the best score stays).
  void restart(const World& world);
  /// Observes the world after a step. When this step parks the car, the score is offered to the
  /// best scores and saved if better (unless the run does not keep bests). Returns true on the
  /// step that ends the run.
  bool observe(const World& world);

  /// The challenge, or null when the scene has no goal.
  [[nodiscard]] const ParkingChallenge* challenge() const {
    return challenge_ ? &*challenge_ : nullptr;
  }
  /// Parked or out of time: the run is decided and the world should stop stepping.
  [[nodiscard]] bool over() const {
    return challenge_ && (challenge_->parkedFrame() || challenge_->timedOut());
  }
  /// The best score before this run (or the one just beaten), if any.
  [[nodiscard]] const std::optional<ParkingScore>& best() const { return best_before_; }
  /// This run's score was saved as the new best.
  [[nodiscard]] bool newBest() const { return new_best_; }
  /// Warnings to show once (corrupt best-scores file, save failure); cleared by takeWarning().
  [[nodiscard]] std::string takeWarning();

 private:
  void finish();  // offers a parked score to the best scores and saves them when it is better
  std::string scene_name_;
  std::string best_path_;
  bool keeps_best_ = true;
  BestScores scores_;
  std::optional<ParkingChallenge> challenge_;
  std::optional<ParkingScore> best_before_;
  bool new_best_ = false;
  std::string warning_;
};

}  // namespace cardemo
