// End-to-end tests of `cardemo compare` and `cardemo collide --oracle`: exit statuses, JSON fields.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/cli_run.hpp"

namespace {

using cardemo::test::CliResult;

std::string replay(const std::string& name) {
  return std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/" + name;
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  return cardemo::test::writeScratch(name, text);
}

TEST(CompareCli, HelpSucceeds) {
  EXPECT_EQ(cardemo::test::runCardemo("compare --help").status, 0);
  EXPECT_EQ(cardemo::test::runCardemo("compare-sweep --help").status, 0);
}

TEST(CompareCli, JsonHasTheContractFields) {
  const CliResult r =
      cardemo::test::runCardemo("compare " + replay("head-on.replay") + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j.at("frames").get<int>(), 0);
  EXPECT_GT(j.at("pairs_checked").get<int>(), 0);
  for (const char* key : {"exact", "box2d", "ours", "box2d_skin"}) {
    SCOPED_TRACE(key);
    const nlohmann::json& t = j.at(key);
    EXPECT_EQ(t.at("agree").get<long long>() + t.at("disagree").get<long long>() +
                  t.at("borderline").get<long long>(),
              j.at("pairs_checked").get<long long>());
  }
  EXPECT_EQ(j.at("exact").at("disagree"), 0);
  ASSERT_TRUE(j.at("box2d").at("hits").is_array());
  ASSERT_FALSE(j.at("box2d").at("hits").empty());
  EXPECT_TRUE(j.at("box2d").at("hits")[0].contains("frame"));
  EXPECT_EQ(j.at("box2d").at("hits")[0].at("id"), "E1");
  EXPECT_FALSE(j.contains("radius"));
  EXPECT_NE(r.err.find("box2d"), std::string::npos);  // the table goes to stderr with --json -
}

TEST(CompareCli, RadiusIsReported) {
  const auto json = cardemo::test::scratchDir() / "out.json";
  const CliResult r = cardemo::test::runCardemo("compare " + replay("demo.replay") +
                                                " --radius 8 --json " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("within"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(cardemo::test::slurp(json)).at("radius"), 8.0);
}

TEST(CompareCli, BadInputExitsTwoWithFileAndLine) {
  const auto bad = writeTemp("bad.replay", "cardemo-replay 1\nscene x.json\n5 Q\n");
  const CliResult r =
      cardemo::test::runCardemo("compare " + bad.string() + " --scene " +
                                std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/garage.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(bad.string() + ":3:"), std::string::npos) << r.err;
  EXPECT_EQ(cardemo::test::runCardemo("compare /nonexistent.replay").status, 2);
  EXPECT_EQ(cardemo::test::runCardemo("compare " + replay("demo.replay") + " --radius -1").status,
            2);
  EXPECT_EQ(cardemo::test::runCardemo("compare").status, 2);
}

// A missing scene is reported on the replay line that names it, or as the option that names it.
TEST(CompareCli, MissingSceneIsReportedWhereItIsNamed) {
  const auto p = writeTemp("drive.replay", "cardemo-replay 1\nscene ../scenes/nope.json\n10 U\n");
  const std::string no_file = ": cannot open: No such file or directory\n";
  for (const char* command : {"compare ", "compare-world "}) {
    const CliResult r = cardemo::test::runCardemo(command + p.string());
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(r.err, p.string() + ":2: scene ../scenes/nope.json" + no_file) << command;
    const CliResult o =
        cardemo::test::runCardemo(command + replay("demo.replay") + " --scene /nonexistent/x.json");
    EXPECT_EQ(o.status, 2) << command;
    EXPECT_EQ(o.err, "--scene /nonexistent/x.json" + no_file) << command;
  }
}

TEST(CompareCli, CollideOracleColumns) {
  const std::string rows = "-1,0,0,2,2,1,0,0,2,2\n0,0,0,2,2,5,0,0,2,2\n";
  const CliResult r = cardemo::test::runCardemo("collide - --oracle exact,box2d", rows);
  ASSERT_EQ(r.status, 0) << r.err;
  // hit,sep,nx,ny,exact_hit,exact_sep,b2_overlap,b2_points
  EXPECT_EQ(r.out, "1,0,1,0,1,0,1,2\n0,3,1,0,0,3,0,0\n");
  EXPECT_EQ(cardemo::test::runCardemo("collide - --oracle nope", rows).status, 2);
  EXPECT_EQ(cardemo::test::runCardemo("collide - --dim 3 --oracle box2d", rows).status, 2);
}

}  // namespace
