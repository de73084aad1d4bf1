#include "io/asset_lookup.hpp"

#include <cstdlib>
#include <system_error>

#include "io/printable.hpp"

namespace cardemo {

namespace fs = std::filesystem;

std::vector<fs::path> assetRoots(std::string_view env_folder, const fs::path& executable) {
  std::vector<fs::path> roots;
  if (!env_folder.empty()) roots.emplace_back(env_folder);
  if (executable.empty()) return roots;
  fs::path folder = executable.parent_path();
  for (int level = 0; level <= kAssetParentLevels && !folder.empty(); ++level) {
    roots.push_back(folder / "assets");
    if (folder == folder.root_path()) break;
    folder = folder.parent_path();
  }
  return roots;
}

std::vector<fs::path> assetRoots() {
  const char* env = std::getenv(kAssetsVariable);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return assetRoots(env == nullptr ? std::string_view() : std::string_view(env),
                    ec ? fs::path() : exe);
}

std::optional<std::string> findAssetIn(const std::vector<fs::path>& roots,
                                       std::string_view relative, std::string* why) {
  for (const fs::path& root : roots) {
    const fs::path candidate = root / relative;
    std::error_code ec;
    if (fs::exists(candidate, ec)) return candidate.lexically_normal().string();
  }
  if (why != nullptr) {
    std::string searched;
    for (const fs::path& root : roots) {
      // Long enough for any path; control bytes escaped, so the message stays one line.
      searched +=
          (searched.empty() ? "" : ", ") + printable(root.lexically_normal().string(), 4096);
    }
    *why = std::string(relative) + ": not found in the assets folders (" +
           (searched.empty() ? std::string("none") : searched) + "); set " + kAssetsVariable +
           " to the assets folder";
  }
  return std::nullopt;
}

std::optional<std::string> findAsset(std::string_view relative, std::string* why) {
  return findAssetIn(assetRoots(), relative, why);
}

}  // namespace cardemo
