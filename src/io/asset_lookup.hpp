#pragma once
/// Finding the bundled assets (scenes, replays, sounds, sprites, the font) at run time.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cardemo {

/// The one environment variable that names the assets folder.
inline constexpr const char* kAssetsVariable = "CARDEMO_ASSETS";

/// How many parents of the executable's folder are searched for `assets/` (a build folder inside
/// the repository is one level down, a test executable two).
inline constexpr int kAssetParentLevels = 3;

/// The folders searched for assets, in order: `env_folder` when not empty, then `assets/` in the
/// folder of `executable` and in each of its first kAssetParentLevels parents. Nothing is baked
/// in at compile time; a platform with its own file system passes its own root as `env_folder`.
[[nodiscard]] std::vector<std::filesystem::path> assetRoots(
    std::string_view env_folder, const std::filesystem::path& executable);

/// assetRoots() for this process: $CARDEMO_ASSETS and the executable (/proc/self/exe).
[[nodiscard]] std::vector<std::filesystem::path> assetRoots();

/// Full path of `relative` (a file or folder, e.g. "sprites/car.png") under the first of `roots`
/// that holds it. Otherwise nullopt, and `why` (when given) gets one line:
/// `RELATIVE: not found in the assets folders (...searched...); set CARDEMO_ASSETS to one`.
[[nodiscard]] std::optional<std::string> findAssetIn(
    const std::vector<std::filesystem::path>& roots, std::string_view relative,
    std::string* why = nullptr);

/// findAssetIn(assetRoots(), relative, why).
[[nodiscard]] std::optional<std::string> findAsset(std::string_view relative,
                                                   std::string* why = nullptr);

}  // namespace cardemo
