// End-to-end test of `cardemo compare-world`: exit statuses and the findings it must print.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct WorldRun {
  int status = -1;
  std::string out;
};

// Runs `cardemo ARGS`, capturing stdout (stderr discarded) and the exit status.
WorldRun cardemo(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path() / "cardemo_compare_world_cli_test";
  std::filesystem::create_directories(dir);
  const auto out =
      dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".out");
  const std::string command =
      std::string(CARDEMO_BINARY) + " " + args + " >" + out.string() + " 2>/dev/null";
  const int raw = std::system(command.c_str());
  std::ifstream f(out, std::ios::binary);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1,
          {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()}};
}

TEST(CompareWorldCli, HeadOnReportsLagAndClamp) {
  const WorldRun r = cardemo("compare-world " + std::string(CARDEMO_SOURCE_DIR) +
                             "/assets/replays/head-on.replay");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("lag"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("E1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed clamp"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("b2_maxTranslation"), std::string::npos) << r.out;
}

TEST(CompareWorldCli, MissingFileExitsTwo) {
  EXPECT_EQ(cardemo("compare-world /nonexistent/missing.replay").status, 2);
}

}  // namespace
