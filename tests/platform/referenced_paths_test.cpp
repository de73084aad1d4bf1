// `cardemo render` and `cardemo play --replay` report a missing scene on the replay line that
// names it (or as the option that names it), before any window or picture is made.

#include <gtest/gtest.h>

#include <string>

#include "../support/cli_run.hpp"

namespace cardemo {
namespace {

const std::string kNoFile = ": cannot open: No such file or directory\n";

std::string replayNamingMissingScene() {
  return test::writeScratch("drive.replay", "cardemo-replay 1\nscene ../scenes/nope.json\n10 U\n")
      .string();
}

TEST(ReferencedPaths, RenderNamesTheReplayLine) {
  const std::string replay = replayNamingMissingScene();
  const std::string out = (test::scratchDir() / "out.png").string();
  const test::CliResult r =
      test::runCardemo("render " + replay + " --out " + out, "", "env -u DISPLAY");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, replay + ":2: scene ../scenes/nope.json" + kNoFile);
  const test::CliResult o = test::runCardemo("render " + test::assetPath("replays/demo.replay") +
                                                 " --scene /nonexistent/x.json --out " + out,
                                             "", "env -u DISPLAY");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "--scene /nonexistent/x.json" + kNoFile);
}

// The scene is read before any window opens, so a display that does not exist is never reached.
TEST(ReferencedPaths, PlayReplayNamesTheReplayLine) {
  const std::string replay = replayNamingMissingScene();
  const test::CliResult r =
      test::runCardemo("play --replay " + replay, "", "env DISPLAY=:cardemo-no-such-display");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, replay + ":2: scene ../scenes/nope.json" + kNoFile);
}

}  // namespace
}  // namespace cardemo
