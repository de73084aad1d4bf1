// End-to-end test of `cardemo compare-world`: exit statuses and the findings it must print.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/cli_run.hpp"

namespace {

using WorldRun = cardemo::test::CliResult;

TEST(CompareWorldCli, HeadOnReportsLagAndClamp) {
  const WorldRun r = cardemo::test::runCardemo("compare-world " + std::string(CARDEMO_SOURCE_DIR) +
                                               "/assets/replays/head-on.replay");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("lag"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("E1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed clamp"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("b2_maxTranslation"), std::string::npos) << r.out;
}

TEST(CompareWorldCli, MissingFileExitsTwo) {
  EXPECT_EQ(cardemo::test::runCardemo("compare-world /nonexistent/missing.replay").status, 2);
}

}  // namespace
