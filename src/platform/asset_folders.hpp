#pragma once
/// Where the bundled assets/ folder is: the game finds its scenes and its font there.

#include <filesystem>
#include <vector>

namespace cardemo {

/// Folders that may hold the bundled assets, in the order to try: $CARDEMO_ASSETS when set, then
/// next to the executable (a build folder inside the repository, or an installed share/cardemo).
[[nodiscard]] std::vector<std::filesystem::path> assetFolders();

}  // namespace cardemo
