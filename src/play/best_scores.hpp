#pragma once
/// The best parking score per scene, and the best bay chain of free drive per scene, kept in a
/// small JSON file in the user's data folder.

#include <map>
#include <string>

#include "sim/bay_chain.hpp"
#include "sim/parking_goal.hpp"

namespace cardemo {

/// Best scores by scene name.
struct BestScores {
  std::map<std::string, ParkingScore> by_scene;  ///< Scene name -> its best score.
  std::map<std::string, ChainScore> chains;      ///< Scene name -> its best bay chain.

  /// Keeps `score` for `scene` when it beats the stored one (or none is stored); true when kept.
  bool offer(const std::string& scene, const ParkingScore& score);
  /// The stored score of `scene`, or null.
  [[nodiscard]] const ParkingScore* find(const std::string& scene) const;
  /// Keeps the bay chain `score` for `scene` when it beats the stored one (or none is stored);
  /// true when kept.
  bool offerChain(const std::string& scene, const ChainScore& score);
  /// The stored bay chain of `scene`, or null.
  [[nodiscard]] const ChainScore* findChain(const std::string& scene) const;
};

/// `$XDG_DATA_HOME/cardemo/best-scores.json`, else `$HOME/.local/share/cardemo/best-scores.json`
/// (relative XDG_DATA_HOME values are ignored, as the XDG spec says); empty when neither is set.
[[nodiscard]] std::string bestScoresPath();

/// Reads the file. A missing file gives no scores and no warning; an unreadable or corrupt one
/// gives no scores and a one-line `warning` (the game goes on and later overwrites it).
[[nodiscard]] BestScores loadBestScores(const std::string& path, std::string& warning);

/// Writes the file atomically, creating its folder; empty on success, else what went wrong.
[[nodiscard]] std::string saveBestScores(const std::string& path, const BestScores& scores);

/// The file's text (`cardemo-best/1` JSON; `bay_chains` only when there is one).
[[nodiscard]] std::string bestScoresText(const BestScores& scores);

}  // namespace cardemo
