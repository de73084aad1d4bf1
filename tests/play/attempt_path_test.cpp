// attemptPath: the numbered recording of each attempt.

#include "play/attempt_path.hpp"

#include <gtest/gtest.h>

#include <set>

namespace cardemo {
namespace {

TEST(AttemptPath, FirstAttemptIsTheGivenPath) {
  EXPECT_EQ(attemptPath("drive.replay", 1), "drive.replay");
  EXPECT_EQ(attemptPath("out/drive", 1), "out/drive");
}

TEST(AttemptPath, LaterAttemptsNumberBeforeTheExtension) {
  EXPECT_EQ(attemptPath("drive.replay", 2), "drive-2.replay");
  EXPECT_EQ(attemptPath("drive.replay", 3), "drive-3.replay");
  EXPECT_EQ(attemptPath("/tmp/x/drive.replay", 12), "/tmp/x/drive-12.replay");
}

TEST(AttemptPath, NamedEdgeCases) {
  EXPECT_EQ(attemptPath("out/drive", 2), "out/drive-2");
  EXPECT_EQ(attemptPath("a.b/run", 2), "a.b/run-2");
  EXPECT_EQ(attemptPath("a.b/run.x.replay", 2), "a.b/run.x-2.replay");
  EXPECT_EQ(attemptPath(".replay", 2), ".replay-2");
  EXPECT_EQ(attemptPath("dir/.replay", 2), "dir/.replay-2");
  EXPECT_EQ(attemptPath("drive.", 2), "drive-2.");
}

TEST(AttemptPath, EveryAttemptGetsItsOwnFile) {
  for (const char* base : {"drive.replay", "drive", "d/.r", "x.y/z"}) {
    std::set<std::string> seen;
    for (int attempt = 1; attempt <= 200; ++attempt) {
      EXPECT_TRUE(seen.insert(attemptPath(base, attempt)).second) << base << " " << attempt;
    }
  }
}

}  // namespace
}  // namespace cardemo
