#include "play/level_list.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <tuple>

#include "io/scene_json.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo {

std::vector<LevelEntry> listLevels(const std::string& assets_folder,
                                   std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  std::vector<LevelEntry> levels;
  const fs::path folder = fs::path(assets_folder) / "scenes" / "levels";
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".json") files.push_back(it->path());
  }
  for (const fs::path& file : files) {
    const Parsed<Scene> scene = loadScene(file.string());
    if (!scene.ok()) {
      warnings.push_back(scene.error().toString());
      continue;
    }
    if (!scene.value().level) continue;
    const LevelInfo& level = *scene.value().level;
    levels.push_back({file.lexically_normal().string(), level.title, scene.value().name,
                      level.order, false, level.task});
  }
  std::sort(levels.begin(), levels.end(), [](const LevelEntry& a, const LevelEntry& b) {
    return std::tie(a.order, a.title, a.path) < std::tie(b.order, b.title, b.path);
  });
  const fs::path lot = fs::path(assets_folder) / "scenes" / "parking-lot.json";
  if (fs::is_regular_file(lot, ec)) {
    levels.push_back(
        {lot.lexically_normal().string(), "Free drive", "parking-lot", 0, true, chainTaskText()});
  }
  return levels;
}

std::optional<std::size_t> nextLevel(const std::vector<LevelEntry>& entries, std::size_t current) {
  if (current >= entries.size() || entries[current].free_drive) return std::nullopt;
  for (std::size_t i = current + 1; i < entries.size(); ++i) {
    if (!entries[i].free_drive) return i;
  }
  return std::nullopt;
}

LevelProgress levelProgress(const std::vector<LevelEntry>& entries, const BestScores& best) {
  LevelProgress progress;
  for (const LevelEntry& e : entries) {
    if (e.free_drive) continue;
    ++progress.levels;
    if (const ParkingScore* score = best.find(e.scene_name)) {
      ++progress.parked;
      progress.stars += std::clamp(score->stars, 0, kMaxStars);
    }
  }
  return progress;
}

std::string progressText(const LevelProgress& progress) {
  if (progress.levels <= 0) return {};
  return std::to_string(progress.parked) + " / " + std::to_string(progress.levels) +
         " levels parked     \xE2\x98\x85 " + std::to_string(progress.stars) + " / " +
         std::to_string(progress.possibleStars());
}

int moveSelection(int selected, int delta, int count) {
  if (count <= 0) return 0;
  const int moved = (selected + delta) % count;
  return moved < 0 ? moved + count : moved;
}

}  // namespace cardemo
