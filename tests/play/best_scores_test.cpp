#include "play/best_scores.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "../support/temp_dir.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for one test and restores it after.
class EnvGuard {
 public:
  EnvGuard(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      setenv(name, value->c_str(), 1);
    } else {
      unsetenv(name);
    }
  }
  ~EnvGuard() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  EnvGuard(const EnvGuard&) = delete;
  EnvGuard& operator=(const EnvGuard&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(BestScoresPath, XdgDataHomeFirstThenHome) {
  const EnvGuard xdg("XDG_DATA_HOME", "/data/me");
  const EnvGuard home("HOME", "/home/me");
  EXPECT_EQ(bestScoresPath(), "/data/me/cardemo/best-scores.json");
}

TEST(BestScoresPath, RelativeOrEmptyXdgFallsBackToHome) {
  const EnvGuard home("HOME", "/home/me");
  {
    const EnvGuard xdg("XDG_DATA_HOME", "relative/data");
    EXPECT_EQ(bestScoresPath(), "/home/me/.local/share/cardemo/best-scores.json");
  }
  {
    const EnvGuard xdg("XDG_DATA_HOME", "");
    EXPECT_EQ(bestScoresPath(), "/home/me/.local/share/cardemo/best-scores.json");
  }
}

TEST(BestScoresPath, NeitherSetGivesNoPath) {
  const EnvGuard xdg("XDG_DATA_HOME", std::nullopt);
  const EnvGuard home("HOME", std::nullopt);
  EXPECT_EQ(bestScoresPath(), "");
  EXPECT_NE(saveBestScores("", BestScores{}), "");
}

TEST(BestScores, OfferKeepsOnlyBetterScores) {
  BestScores b;
  EXPECT_TRUE(b.offer("lvl", {1200, 10.0, 5, 2}));
  EXPECT_FALSE(b.offer("lvl", {1300, 10.8, 5, 2}));  // slower
  EXPECT_EQ(b.find("lvl")->frames, 1200);
  EXPECT_TRUE(b.offer("lvl", {1500, 12.5, 0, 3}));  // more stars beats faster
  EXPECT_EQ(b.find("lvl")->stars, 3);
  EXPECT_FALSE(b.offer("lvl", {1500, 12.5, 0, 3}));  // equal is not better
  EXPECT_EQ(b.find("other"), nullptr);
}

TEST(BestScores, OfferChainKeepsMoreBaysThenSooner) {
  BestScores b;
  EXPECT_TRUE(b.offerChain("lot", {3, 12000, 100.0}));
  EXPECT_FALSE(b.offerChain("lot", {2, 600, 5.0}));      // fewer bays
  EXPECT_FALSE(b.offerChain("lot", {3, 12000, 100.0}));  // equal is not better
  EXPECT_TRUE(b.offerChain("lot", {3, 11880, 99.0}));    // as many, sooner
  EXPECT_EQ(b.findChain("lot")->frames, 11880);
  EXPECT_EQ(b.findChain("other"), nullptr);
  EXPECT_EQ(b.find("lot"), nullptr) << "a chain is not a level's score";
}

TEST(BestScores, ChainsRoundTripBesideTheLevelsAndAreLeftOutWhenNone) {
  const fs::path dir = testing::freshTempDir("best_test_chains");
  const std::string path = (dir / "best-scores.json").string();
  BestScores b;
  ASSERT_TRUE(b.offer("level-1-straight", {529, 529.0 / 120.0, 0, 3}));
  EXPECT_EQ(bestScoresText(b).find("bay_chains"), std::string::npos);
  ASSERT_TRUE(b.offerChain("parking-lot", {4, 14321, 14321.0 / 120.0}));
  ASSERT_EQ(saveBestScores(path, b), "");
  const nlohmann::json j = nlohmann::json::parse(bestScoresText(b));
  EXPECT_EQ(j["format"], "cardemo-best/1");
  EXPECT_EQ(j["bay_chains"]["parking-lot"]["count"], 4);
  std::string warning;
  const BestScores read = loadBestScores(path, warning);
  EXPECT_EQ(warning, "");
  ASSERT_NE(read.findChain("parking-lot"), nullptr);
  EXPECT_EQ(read.findChain("parking-lot")->count, 4);
  EXPECT_EQ(read.findChain("parking-lot")->frames, 14321);
  EXPECT_EQ(read.findChain("parking-lot")->seconds, 14321.0 / 120.0);
  EXPECT_EQ(read.find("level-1-straight")->frames, 529);
  // Saving a level's score again keeps the chains (both live in the one file).
  BestScores again = read;
  ASSERT_TRUE(again.offer("level-1-straight", {500, 500.0 / 120.0, 0, 3}));
  ASSERT_EQ(saveBestScores(path, again), "");
  EXPECT_EQ(loadBestScores(path, warning).findChain("parking-lot")->count, 4);
  fs::remove_all(dir);
}

TEST(BestScores, SaveCreatesTheFolderAndLoadReadsItBack) {
  const fs::path dir = testing::freshTempDir("best_test_roundtrip");
  const EnvGuard xdg("XDG_DATA_HOME", dir.string());
  const std::string path = bestScoresPath();
  EXPECT_FALSE(fs::exists(fs::path(path).parent_path()));
  BestScores b;
  ASSERT_TRUE(b.offer("level-1-straight", {529, 529.0 / 120.0, 0, 3}));
  ASSERT_TRUE(b.offer("level \"2\"", {900, 7.5, 10, 2}));
  ASSERT_EQ(saveBestScores(path, b), "");
  std::string warning;
  const BestScores read = loadBestScores(path, warning);
  EXPECT_EQ(warning, "");
  ASSERT_EQ(read.by_scene.size(), 2u);
  const ParkingScore* s = read.find("level-1-straight");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->frames, 529);
  EXPECT_EQ(s->seconds, 529.0 / 120.0);  // shortest round-trip text reads back bit for bit
  EXPECT_EQ(s->damage, 0);
  EXPECT_EQ(s->stars, 3);
  EXPECT_EQ(read.find("level \"2\"")->damage, 10);
  // No temporary file is left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(fs::path(path).parent_path())) {
    ++files;
  }
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}

TEST(BestScores, MissingFileIsEmptyWithoutWarning) {
  const fs::path dir = testing::freshTempDir("best_test_missing");
  std::string warning = "stale";
  const BestScores b = loadBestScores((dir / "none.json").string(), warning);
  EXPECT_TRUE(b.by_scene.empty());
  EXPECT_EQ(warning, "");
  fs::remove_all(dir);
}

TEST(BestScores, CorruptFilesAreIgnoredWithOneLineWarning) {
  const fs::path dir = testing::freshTempDir("best_test_corrupt");
  const fs::path path = dir / "best-scores.json";
  const std::string good_entry = R"({"frames": 10, "seconds": 1, "damage": 0, "stars": 3})";
  for (const std::string& text : {
           std::string("\xff\xfe garbage"),
           std::string("{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": "),  // truncated
           std::string(""),
           std::string("[]"),
           std::string("{\"format\": \"other/1\", \"scenes\": {}}"),
           std::string("{\"format\": \"cardemo-best/1\", \"scenes\": []}"),
           "{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": " + good_entry +
               ", \"b\": {\"frames\": 10, \"seconds\": 1, \"damage\": 0, \"stars\": 7}}}",
           std::string("{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": {\"frames\": -1, "
                       "\"seconds\": 1, \"damage\": 0, \"stars\": 1}}}"),
           std::string("{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": {\"frames\": 1}}}"),
           "{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": " + good_entry +
               "}, \"bay_chains\": []}",
           "{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": " + good_entry +
               "}, \"bay_chains\": {\"lot\": {\"count\": 0, \"frames\": 0, \"seconds\": 0}}}",
           "{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": " + good_entry +
               "}, \"bay_chains\": {\"lot\": {\"count\": 2, \"seconds\": 3}}}",
           "{\"format\": \"cardemo-best/1\", \"scenes\": {\"a\": " + good_entry +
               "}, \"bay_chains\": {\"lot\": {\"count\": 2, \"frames\": 360, "
               "\"seconds\": \"3\"}}}",
       }) {
    writeText(path, text);
    std::string warning;
    const BestScores b = loadBestScores(path.string(), warning);
    EXPECT_TRUE(b.by_scene.empty()) << text;
    EXPECT_TRUE(b.chains.empty()) << text;
    EXPECT_NE(warning.find(path.string() + ": "), std::string::npos) << text;
    EXPECT_NE(warning.find("best scores ignored"), std::string::npos) << text;
    EXPECT_EQ(warning.find('\n'), std::string::npos) << text;
  }
  // A corrupt file is replaced by the next save.
  BestScores b;
  ASSERT_TRUE(b.offer("a", {10, 1.0, 0, 3}));
  ASSERT_EQ(saveBestScores(path.string(), b), "");
  std::string warning;
  EXPECT_EQ(loadBestScores(path.string(), warning).by_scene.size(), 1u);
  EXPECT_EQ(warning, "");
  fs::remove_all(dir);
}

TEST(BestScores, AFolderInPlaceOfTheFileIsUnreadable) {
  const fs::path dir = testing::freshTempDir("best_test_folder");
  const fs::path path = dir / "best-scores.json";
  fs::create_directories(path);
  std::string warning;
  EXPECT_TRUE(loadBestScores(path.string(), warning).by_scene.empty());
  EXPECT_NE(warning.find("best scores ignored"), std::string::npos);
  EXPECT_NE(saveBestScores(path.string(), BestScores{}), "");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cardemo
