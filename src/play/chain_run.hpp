#pragma once
/// Free drive's bay chain being played: the chain beside the session's World on a scene without a
/// goal, and its best count kept with the levels' best scores (saved when the chain ends with a
/// better one).

#include <optional>
#include <string>

#include "play/best_scores.hpp"
#include "sim/bay_chain.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// The bay chain of the scene being played (nothing when the scene has a goal or no free bay).
class ChainRun {
 public:
  /// Starts on `world`'s frame; `best_path` is the best-scores file (empty: bests not kept). With
  /// `keeps_best` false (a replay being watched) the stored best is shown but never replaced.
  ChainRun(const World& world, std::string best_path, bool keeps_best = true);

  /// A fresh chain for a restarted world (the best stays).
  void restart(const World& world);
  /// Observes the world after a step; when the chain ends its count is offered to the best and
  /// saved if better (unless the run does not keep bests). Returns true on the step that ends it.
  bool observe(const World& world);

  /// The chain, or null when the scene has a goal or no free bay (plain free drive).
  [[nodiscard]] const BayChain* chain() const { return chain_ ? &*chain_ : nullptr; }
  /// The chain ended (time up or wrecked): the world should stop stepping.
  [[nodiscard]] bool over() const { return chain_ && chain_->over(); }
  /// The best chain before this run (or the one just beaten), if any.
  [[nodiscard]] const std::optional<ChainScore>& best() const { return best_before_; }
  /// This run's chain was saved as the new best.
  [[nodiscard]] bool newBest() const { return new_best_; }
  /// Warnings to show once (corrupt best-scores file, save failure); cleared by takeWarning().
  [[nodiscard]] std::string takeWarning();

 private:
  void finish();  // offers the final count to the best and saves it when it is better
  std::string scene_name_;
  std::string best_path_;
  bool keeps_best_ = true;
  bool has_bays_ = false;
  BestScores scores_;
  std::optional<BayChain> chain_;
  std::optional<ChainScore> best_before_;
  bool new_best_ = false;
  std::string warning_;
};

}  // namespace cardemo
