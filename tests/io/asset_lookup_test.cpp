// The one asset lookup: the folders searched and their order, CARDEMO_ASSETS, the depth limit
// above the executable, and the message for a missing asset.

#include "io/asset_lookup.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "../support/temp_dir.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << "x";
}

// Sets CARDEMO_ASSETS (or unsets it, for nullopt) for one test, and puts it back afterwards.
class AssetsVariable {
 public:
  explicit AssetsVariable(const std::optional<std::string>& value) {
    if (const char* old = std::getenv(kAssetsVariable)) saved_ = old;
    if (value) {
      ::setenv(kAssetsVariable, value->c_str(), 1);
    } else {
      ::unsetenv(kAssetsVariable);
    }
  }
  ~AssetsVariable() {
    if (saved_) {
      ::setenv(kAssetsVariable, saved_->c_str(), 1);
    } else {
      ::unsetenv(kAssetsVariable);
    }
  }
  AssetsVariable(const AssetsVariable&) = delete;
  AssetsVariable& operator=(const AssetsVariable&) = delete;

 private:
  std::optional<std::string> saved_;
};

fs::path runningExecutable() {
  std::error_code ec;
  return fs::read_symlink("/proc/self/exe", ec);
}

TEST(AssetLookup, SearchesTheVariableThenTheExecutablesFolderAndItsParents) {
  const fs::path exe = "/r/repo/build/bin/cardemo";
  const std::vector<fs::path> expected{"/env/assets", "/r/repo/build/bin/assets",
                                       "/r/repo/build/assets", "/r/repo/assets", "/r/assets"};
  EXPECT_EQ(assetRoots("/env/assets", exe), expected);
  EXPECT_EQ(assetRoots("", exe), std::vector<fs::path>(expected.begin() + 1, expected.end()))
      << "an empty variable is no folder";
  EXPECT_EQ(assetRoots("", "/cardemo"), std::vector<fs::path>{"/assets"}) << "stops at the root";
  EXPECT_EQ(assetRoots("rel", ""), std::vector<fs::path>{"rel"}) << "no executable known";
  EXPECT_EQ(static_cast<int>(assetRoots("", exe).size()), kAssetParentLevels + 1);
}

TEST(AssetLookup, TheFirstFolderHoldingTheAssetWins) {
  const fs::path base = testing::freshTempDir("asset_order");
  const fs::path env = base / "env";
  const fs::path exe = base / "repo" / "build" / "cardemo";
  const std::vector<fs::path> roots = assetRoots(env.string(), exe);
  touch(env / "sprites/car.png");
  touch(base / "repo/build/assets/sprites/car.png");
  touch(base / "repo/assets/sprites/car.png");
  touch(base / "repo/assets/fonts/DejaVuSans.ttf");
  fs::create_directories(base / "repo/assets/sounds");

  EXPECT_EQ(findAssetIn(roots, "sprites/car.png"), (env / "sprites/car.png").string());
  EXPECT_EQ(findAssetIn(roots, "fonts/DejaVuSans.ttf"),
            (base / "repo/assets/fonts/DejaVuSans.ttf").string())
      << "an asset missing from the first folders is looked for in the next";
  EXPECT_EQ(findAssetIn(roots, "sounds"), (base / "repo/assets/sounds").string())
      << "a folder is an asset too";
  fs::remove(env / "sprites/car.png");
  EXPECT_EQ(findAssetIn(roots, "sprites/car.png"),
            (base / "repo/build/assets/sprites/car.png").string())
      << "the executable's nearest folder before its parents";
  fs::remove_all(base);
}

TEST(AssetLookup, OnlyAFewParentsOfTheExecutableAreSearched) {
  const fs::path base = testing::freshTempDir("asset_depth");
  touch(base / "assets/scenes/lot.json");
  fs::path exe = base;
  for (int level = 0; level <= kAssetParentLevels; ++level) exe /= "d" + std::to_string(level);
  EXPECT_EQ(findAssetIn(assetRoots("", exe / "cardemo"), "scenes/lot.json"), std::nullopt);
  EXPECT_EQ(findAssetIn(assetRoots("", exe.parent_path() / "cardemo"), "scenes/lot.json"),
            (base / "assets/scenes/lot.json").string());
  fs::remove_all(base);
}

TEST(AssetLookup, TheEnvironmentVariableComesFirst) {
  const fs::path base = testing::freshTempDir("asset_env");
  touch(base / "replays/only-here.replay");
  {
    const AssetsVariable set(base.string());
    const std::vector<fs::path> roots = assetRoots();
    ASSERT_FALSE(roots.empty());
    EXPECT_EQ(roots.front(), base);
    EXPECT_EQ(roots, assetRoots(base.string(), runningExecutable()));
    EXPECT_EQ(findAsset("replays/only-here.replay"), (base / "replays/only-here.replay").string());
  }
  {
    const AssetsVariable unset(std::nullopt);
    EXPECT_EQ(assetRoots(), assetRoots("", runningExecutable()));
    EXPECT_EQ(findAsset("replays/only-here.replay"), std::nullopt);
  }
  fs::remove_all(base);
}

TEST(AssetLookup, AMissingAssetSaysWhereItLookedOnOneLine) {
  std::string why;
  EXPECT_EQ(findAssetIn({"/no/such/dir", "/x/build/../assets"}, "sprites/car.png", &why),
            std::nullopt);
  EXPECT_EQ(why,
            "sprites/car.png: not found in the assets folders (/no/such/dir, /x/assets); set "
            "CARDEMO_ASSETS to the assets folder");
  EXPECT_EQ(findAssetIn({"/odd\nname"}, "fonts/DejaVuSans.ttf", &why), std::nullopt);
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
  EXPECT_NE(why.find("/odd\\x0aname"), std::string::npos) << why;
  EXPECT_EQ(findAssetIn({}, "scenes/lot.json", &why), std::nullopt);
  EXPECT_NE(why.find("(none)"), std::string::npos) << why;
}

}  // namespace
}  // namespace cardemo
