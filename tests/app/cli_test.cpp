// End-to-end tests of the cardemo executable: exit statuses, error lines and outputs.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/cli_run.hpp"

namespace {

using cardemo::test::CliResult;
using cardemo::test::slurp;

CliResult cardemo(const std::string& args, const std::string& stdin_text = "") {
  return cardemo::test::runCardemo(args, stdin_text);
}

std::string asset(const std::string& relative) {
  return cardemo::test::assetPath(relative);
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  return cardemo::test::writeScratch(name, text);
}

int countLines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

TEST(Cli, HelpAndVersionSucceed) {
  EXPECT_EQ(cardemo("--help").status, 0);
  EXPECT_EQ(cardemo("replay --help").status, 0);
  EXPECT_EQ(cardemo("collide --help").status, 0);
  const CliResult v = cardemo("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("cardemo "), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
  for (const char* args : {"", "frobnicate", "replay", "collide x.csv --dim 4", "replay a b c"}) {
    const CliResult r = cardemo(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(countLines(r.err), 1) << args << ": " << r.err;
  }
}

TEST(Cli, MissingReplayNamesTheFile) {
  const CliResult r = cardemo("replay /nonexistent/x.replay");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("/nonexistent/x.replay:", 0), 0u) << r.err;
  EXPECT_EQ(countLines(r.err), 1);
}

TEST(Cli, BadReplayLineIsReported) {
  const auto p = writeTemp("bad.replay", "cardemo-replay 1\nscene " +
                                             asset("scenes/parking-lot.json") + "\n10 U\n5 X\n");
  const CliResult r = cardemo("replay " + p.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind(p.string() + ":4:", 0), 0u) << r.err;
}

TEST(Cli, BadSceneLineIsReported) {
  const auto scene = writeTemp("bad.json",
                               "{\n  \"format\": \"cardemo-scene/1\",\n  \"parked\": [],\n"
                               "  \"player\": {\"x\": 0, \"y\": 0, \"heading_deg\": 0,\n"
                               "    \"length\": -4.5, \"width\": 1.8}\n}\n");
  const auto replay = writeTemp("ok.replay", "cardemo-replay 1\nscene bad.json\n10 U\n");
  const CliResult r = cardemo("replay " + replay.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind(scene.string() + ":5:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("length"), std::string::npos) << r.err;
}

// A missing scene is reported on the line that names it, with both files named.
TEST(Cli, MissingSceneIsReportedWhereItIsNamed) {
  const auto p = writeTemp("drive.replay", "cardemo-replay 1\nscene ../scenes/nope.json\n10 U\n");
  const std::string no_file = ": cannot open: No such file or directory\n";
  const CliResult r = cardemo("replay " + p.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, p.string() + ":2: scene ../scenes/nope.json" + no_file);
  const CliResult o =
      cardemo("replay " + asset("replays/demo.replay") + " --scene /nonexistent/x.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "--scene /nonexistent/x.json" + no_file);
}

TEST(Cli, ReplayWithoutSceneIsAnError) {
  const auto p = writeTemp("noscene.replay", "cardemo-replay 1\n10 U\n");
  const CliResult r = cardemo("replay " + p.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind(p.string() + ":1:", 0), 0u) << r.err;
  // --scene supplies it.
  EXPECT_EQ(cardemo("replay " + p.string() + " --scene " + asset("scenes/parking-lot.json")).status,
            0);
}

TEST(Cli, FailedExpectationExitsOneAndSaysWhat) {
  const auto p =
      writeTemp("expect.replay", "cardemo-replay 1\nscene " + asset("scenes/parking-lot.json") +
                                     "\n10 .\nexpect health 99\nexpect hits 3\n");
  const CliResult r = cardemo("replay " + p.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("health: expected 99, got 100"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hits: expected 3, got 0"), std::string::npos) << r.out;
}

TEST(Cli, JsonSummaryHasTheContractFields) {
  const CliResult r = cardemo("replay " + asset("replays/head-on.replay") + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key :
       {"\"scene\"", "\"hz\"", "\"frames\"", "\"health\"", "\"hits\"", "\"final\"",
        "\"heading_deg\"", "\"hash\"", "\"stats\"", "\"broadphase_queries\"",
        "\"broadphase_candidates\"", "\"narrowphase_tests\"", "\"contacts\""}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  }
  EXPECT_EQ(r.out.front(), '{');  // the human summary went to stderr
}

TEST(Cli, TraceHasOneRowPerFrame) {
  const auto trace = cardemo::test::scratchDir() / "trace.csv";
  std::filesystem::remove(trace);
  const auto replay =
      writeTemp("trace.replay",
                "cardemo-replay 1\nscene " + asset("scenes/parking-lot.json") + "\n30 U\n20 UL\n");
  const CliResult r = cardemo("replay " + replay.string() + " --trace " + trace.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = slurp(trace);
  EXPECT_EQ(csv.rfind("frame,x,y,heading_deg,speed,steer_deg,health,contacts\n", 0), 0u);
  EXPECT_EQ(countLines(csv), 1 + 51);  // header + frames 0..50
}

TEST(Cli, Collide2dRowsInOrder) {
  const std::string csv =
      "ax,ay,ah,al,aw,bx,by,bh,bl,bw\n"
      "# comment\n"
      "0,0,0,4,2,5,0,0,4,2\n"  // gap of 1 along x
      "0,0,0,4,2,4,0,0,4,2\n"  // touching
      "\n"
      "0,0,0,4,2,2.5,0,90,4,2\n";  // B rotated 90: overlap 0.5
  const CliResult r = cardemo("collide -", csv);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "0,1,1,0\n1,0,1,0\n1,-0.5,1,0\n");
}

TEST(Cli, Collide2dExactFarFromTheOrigin) {
  // B (rotated 90 degrees, exact) touches A's +x face exactly, 1e7 m out: a hit with sep 0.
  const CliResult r = cardemo("collide -",
                              "10000000,-10000000,0,4,2,10000003,-10000000,90,4,2\n"
                              "10000000,-10000000,0,4,2,10000003.000001,-10000000,90,4,2\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string second = r.out.substr(r.out.find('\n') + 1);
  EXPECT_EQ(r.out.substr(0, r.out.find('\n') + 1), "1,0,1,0\n");
  EXPECT_EQ(second.rfind("0,", 0), 0u) << second;  // 1 um apart: separated
  EXPECT_NEAR(std::stod(second.substr(2)), 1e-6, 2e-9) << second;
}

TEST(Cli, Collide3dAndBadRows) {
  const CliResult ok = cardemo("collide - --dim 3", "0,0,0,1,0,0,0,2,2,2,3,0,0,1,0,0,0,2,2,2\n");
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.out.rfind("0,1,1,0,0,", 0), 0u) << ok.out;
  const CliResult zero = cardemo("collide - --dim 3", "0,0,0,0,0,0,0,2,2,2,3,0,0,1,0,0,0,2,2,2\n");
  EXPECT_EQ(zero.status, 2);
  EXPECT_EQ(zero.err.rfind("-:1:", 0), 0u) << zero.err;
  const CliResult short_row = cardemo("collide -", "1,2,3\n");
  EXPECT_EQ(short_row.status, 2);
  EXPECT_EQ(short_row.err.rfind("-:1:", 0), 0u) << short_row.err;
}

TEST(Cli, ExpectParkedIsCheckedPrintedAndInTheJson) {
  const std::string level = asset("scenes/levels/level-1-straight.json");
  const std::string golden = slurp(asset("replays/level-1-straight.replay"));
  const auto at = golden.find("expect parked ");
  ASSERT_NE(at, std::string::npos);
  const std::string frame = golden.substr(at + 14, golden.find('\n', at) - at - 14);

  // The golden drive with a wrong parked frame: exit 1 and the difference named.
  std::string inputs;
  for (std::size_t start = 0; start < golden.size();) {
    const std::size_t end = golden.find('\n', start);
    const std::string line = golden.substr(start, end - start);
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) inputs += line + "\n";
    start = end == std::string::npos ? golden.size() : end + 1;
  }
  const auto wrong = writeTemp(
      "parked.replay", "cardemo-replay 1\nscene " + level + "\n" + inputs + "expect parked 5\n");
  const CliResult bad = cardemo("replay " + wrong.string());
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.out.find("FAILED    parked: expected frame 5, got frame " + frame),
            std::string::npos)
      << bad.out;

  const CliResult printed = cardemo("replay " + wrong.string() + " --print-expect");
  EXPECT_NE(printed.out.find("expect parked " + frame + "\n"), std::string::npos) << printed.out;

  const CliResult json = cardemo("replay " + wrong.string() + " --json -");
  EXPECT_NE(json.out.find("\"parked\": " + frame), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"stars\": 3"), std::string::npos) << json.out;

  // Stopping short of the bay: never parked; a scene without a goal cannot satisfy the line.
  const auto never = writeTemp(
      "never.replay", "cardemo-replay 1\nscene " + level + "\n60 U\n200 D\nexpect parked never\n");
  EXPECT_EQ(cardemo("replay " + never.string()).status, 0);
  const auto no_goal =
      writeTemp("nogoal.replay", "cardemo-replay 1\nscene " + asset("scenes/parking-lot.json") +
                                     "\n10 .\nexpect parked never\n");
  const CliResult r = cardemo("replay " + no_goal.string() + " --json -");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("parked: expected never, but the scene has no goal"), std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("\"parked\": null"), std::string::npos) << r.out;
}

// `replay --json` says when the level clock started and why the car is not parked; the human
// summary the same. A drive that waits 2 s first parks with the same seconds.
TEST(Cli, ReplayJsonHasTheClockStartAndWhyNotParked) {
  const std::string level = asset("scenes/levels/level-1-straight.json");
  const auto json_of = [](const std::string& replay) {
    const CliResult r = cardemo("replay " + replay + " --json -");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out, nullptr, false);
  };
  const nlohmann::json golden = json_of(asset("replays/level-1-straight.replay"));
  EXPECT_EQ(golden["clock_start"], 0);
  EXPECT_EQ(golden["not_parked"], nlohmann::json::array());
  ASSERT_TRUE(golden["score"].is_object()) << golden.dump();

  std::string inputs;
  const std::string text = slurp(asset("replays/level-1-straight.replay"));
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) inputs += line + "\n";
    start = end == std::string::npos ? text.size() : end + 1;
  }
  const auto waiting =
      writeTemp("waiting.replay", "cardemo-replay 1\nscene " + level + "\n240 .\n" + inputs);
  const nlohmann::json waited = json_of(waiting.string());
  EXPECT_EQ(waited["clock_start"], 240);
  EXPECT_EQ(waited["parked"], golden["parked"].get<int>() + 240);
  EXPECT_EQ(waited["score"], golden["score"]) << waited.dump();
  const CliResult human = cardemo("replay " + waiting.string());
  EXPECT_NE(human.out.find("from frame 240"), std::string::npos) << human.out;

  // Stopped short of the bay: not parked, and the readout's words say why.
  const auto short_of =
      writeTemp("short.replay", "cardemo-replay 1\nscene " + level + "\n60 U\n200 D\n");
  const nlohmann::json stopped = json_of(short_of.string());
  EXPECT_TRUE(stopped["parked"].is_null());
  ASSERT_TRUE(stopped["not_parked"].is_array());
  ASSERT_FALSE(stopped["not_parked"].empty());
  EXPECT_NE(stopped["not_parked"][0].get<std::string>().find(" m "), std::string::npos)
      << stopped.dump();
  EXPECT_NE(cardemo("replay " + short_of.string()).out.find("parked    never ("),
            std::string::npos);

  // No goal: both null.
  const auto lot = writeTemp(
      "lot.replay", "cardemo-replay 1\nscene " + asset("scenes/parking-lot.json") + "\n10 U\n");
  const nlohmann::json free_drive = json_of(lot.string());
  EXPECT_TRUE(free_drive["clock_start"].is_null());
  EXPECT_TRUE(free_drive["not_parked"].is_null());
}

// `replay --bay-chain` runs free drive's bay chain beside the replay: a car standing in the free
// bay between two cars of a row parks it after the hold, and the next bay is highlighted.
TEST(Cli, ReplayBayChainCountsTheBaysParked) {
  const auto scene = writeTemp("row.json", R"({"format": "cardemo-scene/1", "name": "row",
    "player": {"x": 10, "y": 0, "heading_deg": 90, "length": 4.5, "width": 1.8},
    "parked": [{"id": "a", "x": 0, "y": 0, "heading_deg": 90, "length": 4.5, "width": 1.8},
               {"id": "b", "x": 5, "y": 0, "heading_deg": 90, "length": 4.5, "width": 1.8},
               {"id": "d", "x": 15, "y": 0, "heading_deg": 90, "length": 4.5, "width": 1.8}]})");
  const auto replay =
      writeTemp("row.replay", "cardemo-replay 1\nscene " + scene.string() + "\n70 .\n");
  const CliResult r = cardemo("replay " + replay.string() + " --bay-chain --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(j.is_object()) << r.out;
  EXPECT_EQ(j["bay_chain"]["count"], 1) << j.dump();
  EXPECT_EQ(j["bay_chain"]["bay"], "bay-2") << j.dump();
  EXPECT_EQ(j["bay_chain"]["bays"], 3) << j.dump();
  EXPECT_EQ(j["bay_chain"]["clock_frames"], 0) << "the car never moved";
  EXPECT_NE(r.err.find("bay chain 1 parked of 3 free bays, next bay-2"), std::string::npos)
      << r.err;
  // Without the flag, no chain.
  const CliResult plain = cardemo("replay " + replay.string() + " --json -");
  EXPECT_FALSE(nlohmann::json::parse(plain.out, nullptr, false).contains("bay_chain"));
}

// `replay --json` reports a chain of bays: a car standing in the first of two parks it after the
// hold, and the second is next; a goal of one bay has one.
TEST(Cli, ReplayJsonReportsTheBaysOfAChain) {
  const auto scene = writeTemp("chain.json", R"({"format": "cardemo-scene/1", "name": "chain",
    "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
    "parked": [],
    "goal": {"bay": {"x": 0, "y": 0, "heading_deg": 0, "length": 5.5, "width": 2.6},
             "next_bays": [{"x": 20, "y": 0, "heading_deg": 0, "length": 5.5, "width": 2.6}]}})");
  const auto replay =
      writeTemp("chain.replay", "cardemo-replay 1\nscene " + scene.string() + "\n90 .\n");
  const CliResult r = cardemo("replay " + replay.string() + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(j.is_object()) << r.out;
  EXPECT_EQ(j["bays"]["total"], 2) << j.dump();
  EXPECT_EQ(j["bays"]["parked"], 1) << j.dump();
  EXPECT_EQ(j["bays"]["frames"], nlohmann::json::array({60})) << j.dump();
  EXPECT_TRUE(j["parked"].is_null());
  ASSERT_FALSE(j["not_parked"].empty());
  EXPECT_EQ(j["not_parked"][0], "next bay 2/2");
  EXPECT_NE(r.err.find("bays      1 of 2 parked (frame 60)"), std::string::npos) << r.err;

  const nlohmann::json one = nlohmann::json::parse(
      cardemo("replay " + asset("replays/level-1-straight.replay") + " --json -").out, nullptr,
      false);
  EXPECT_EQ(one["bays"]["total"], 1);
  EXPECT_EQ(one["bays"]["parked"], 1);
  EXPECT_EQ(one["bays"]["frames"], nlohmann::json::array({one["parked"]}));
}

// `replay --json` reports the gates: the slalom's golden weave passes all three, in order; a
// straight drive misses the first, and not_parked names it.
TEST(Cli, ReplayJsonReportsTheGates) {
  const auto json_of = [](const std::string& replay) {
    const CliResult r = cardemo("replay " + replay + " --json -");
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out, nullptr, false);
  };
  const nlohmann::json golden = json_of(asset("replays/level-5-slalom.replay"));
  const nlohmann::json names = {"left of bollard 1", "right of bollard 2", "left of bollard 3"};
  EXPECT_EQ(golden["gates"]["total"], 3);
  EXPECT_EQ(golden["gates"]["passed"], 3);
  EXPECT_EQ(golden["gates"]["names"], names);
  EXPECT_TRUE(golden["gates"]["next"].is_null());
  EXPECT_EQ(golden["gates"]["misses"], 0);

  const auto straight = writeTemp(
      "straight.replay", "cardemo-replay 1\nscene " + asset("scenes/levels/level-5-slalom.json") +
                             "\n700 U\n240 D\n120 .\n");
  const nlohmann::json missed = json_of(straight.string());
  EXPECT_TRUE(missed["parked"].is_null());
  EXPECT_EQ(missed["gates"]["passed"], 0);
  EXPECT_EQ(missed["gates"]["next"], "left of bollard 1");
  EXPECT_GE(missed["gates"]["misses"], 1);
  ASSERT_FALSE(missed["not_parked"].empty());
  EXPECT_EQ(missed["not_parked"][0], "next gate 1: left of bollard 1");
  const CliResult human = cardemo("replay " + straight.string());
  EXPECT_NE(human.out.find("gates     0 of 3 passed"), std::string::npos) << human.out;

  // No goal: null.
  const auto lot = writeTemp(
      "lot.replay", "cardemo-replay 1\nscene " + asset("scenes/parking-lot.json") + "\n10 U\n");
  EXPECT_TRUE(json_of(lot.string())["gates"].is_null());
  EXPECT_TRUE(json_of(lot.string())["bays"].is_null());
}

}  // namespace
