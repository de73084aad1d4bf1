// Recorder: merged runs, periodic flushes visible before finish, atomic publish, round trip; a
// leftover or busy PATH.part is kept and named; a failed write (file-size limit, the same path as
// a full disk) keeps a valid prefix and says so.

#include "play/recorder.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "../support/temp_dir.hpp"
#include "io/replay_text.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

const InputFrame kUp{true, false, false, false};
const InputFrame kUpLeft{true, false, true, false};
const InputFrame kNone{};

TEST(Recorder, MergesRunsAndPublishesOnFinish) {
  const fs::path dir = testing::freshTempDir("recorder_test_merge");
  const fs::path out = dir / "drive.replay";
  {
    Recorder rec(out.string(), (dir / "lot.json").string(), 120, 1000);
    for (int i = 0; i < 5; ++i) rec.record(kUp);
    for (int i = 0; i < 3; ++i) rec.record(kUpLeft);
    rec.record(kNone);
    rec.record({false, false, true, true, true});
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::exists(dir / "drive.replay.part"));
    EXPECT_EQ(rec.frames(), 10);
    EXPECT_EQ(rec.finish("expect health 100\n"), "");
    EXPECT_EQ(rec.finish(), "");  // idempotent
  }
  EXPECT_FALSE(fs::exists(dir / "drive.replay.part"));
  const std::string text = slurp(out);
  EXPECT_EQ(text,
            "cardemo-replay 1\nscene lot.json\nhz 120\n# frames  keys\n5 U\n3 UL\n1 .\n1 LRH\n"
            "expect health 100\n");
}

// The recorder writes its input lines with the replay format's own writer (io/replay_text).
TEST(Recorder, WritesEveryKeySetAsTheReplayFormatDoes) {
  const fs::path dir = testing::freshTempDir("recorder_test_keys");
  const fs::path out = dir / "keys.replay";
  Replay expected;
  {
    Recorder rec(out.string(), "", 120, 25);
    for (int bits = 0; bits < 32; ++bits) {
      const InputRun run{1 + bits % 5, InputFrame::fromBits(static_cast<std::uint8_t>(bits))};
      for (std::int64_t i = 0; i < run.count; ++i) rec.record(run.keys);
      expected.runs.push_back(run);
    }
    ASSERT_EQ(rec.finish(), "");
  }
  const Parsed<Replay> back = parseReplay(slurp(out), "keys.replay");
  ASSERT_TRUE(back.ok()) << back.error().toString();
  // Flush points may split a run in two; the frames and their keys are what must match.
  std::vector<InputFrame> recorded;
  std::vector<InputFrame> played;
  for (const InputRun& run : back.value().runs)
    recorded.insert(recorded.end(), run.count, run.keys);
  for (const InputRun& run : expected.runs) played.insert(played.end(), run.count, run.keys);
  EXPECT_EQ(recorded, played);
  // Without splits (one flush at the end) the body is formatReplay's, line for line.
  {
    const fs::path whole = dir / "whole.replay";
    Recorder rec(whole.string(), "", 120, 1'000'000);
    for (const InputRun& run : expected.runs) {
      for (std::int64_t i = 0; i < run.count; ++i) rec.record(run.keys);
    }
    ASSERT_EQ(rec.finish(), "");
    std::string text = slurp(whole);
    const std::string comment = "# frames  keys\n";
    text.erase(text.find(comment), comment.size());
    EXPECT_EQ(text, formatReplay(expected));
  }
}

TEST(Recorder, FlushesPeriodicallyAsAValidPrefix) {
  const fs::path dir = testing::freshTempDir("recorder_test_flush");
  const fs::path out = dir / "r.replay";
  const fs::path part = dir / "r.replay.part";
  Recorder rec(out.string(), (dir / "lot.json").string(), 60, 10);
  for (int i = 0; i < 25; ++i) rec.record(kUp);
  // Two flushes have happened (frames 10 and 20): 20 frames are on disk, split into runs of 10.
  const std::string on_disk = slurp(part);
  const Parsed<Replay> prefix = parseReplay(on_disk, part.string());
  ASSERT_TRUE(prefix.ok()) << prefix.error().toString();
  EXPECT_EQ(prefix.value().totalFrames(), 20);
  EXPECT_EQ(prefix.value().hz, 60);
  EXPECT_FALSE(fs::exists(out));
  ASSERT_EQ(rec.finish(), "");
  const Parsed<Replay> whole = loadReplay(out.string());
  ASSERT_TRUE(whole.ok()) << whole.error().toString();
  EXPECT_EQ(whole.value().totalFrames(), 25);
}

TEST(Recorder, RoundTripsRandomInputs) {
  const fs::path dir = testing::freshTempDir("recorder_test_roundtrip");
  const fs::path out = dir / "sub" / "r.replay";
  fs::create_directories(out.parent_path());
  std::vector<InputFrame> inputs;
  std::uint32_t seed = 12345;
  InputFrame current;
  for (int i = 0; i < 5000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    if ((seed >> 24) < 20)
      current = InputFrame::fromBits(static_cast<std::uint8_t>(seed >> 8 & 31));  // with H
    inputs.push_back(current);
  }
  {
    Recorder rec(out.string(), (dir / "scenes" / "lot.json").string(), 120, 97);
    for (const InputFrame& in : inputs) rec.record(in);
  }  // the destructor finishes and publishes
  const Parsed<Replay> replay = loadReplay(out.string());
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  EXPECT_EQ(replay.value().scene, "../scenes/lot.json");
  std::vector<InputFrame> back;
  for (const InputRun& run : replay.value().runs) {
    EXPECT_LE(run.count, 97);
    for (std::int64_t k = 0; k < run.count; ++k) back.push_back(run.keys);
  }
  EXPECT_EQ(back, inputs);
}

TEST(Recorder, NamesAFarSceneByItsAbsolutePath) {
  const fs::path dir = testing::freshTempDir("recorder_test_absolute");
  const fs::path out = dir / "r.replay";
  {
    Recorder rec(out.string(), "/usr/share/cardemo/lot.json", 120, 120);
    rec.record(kUp);
  }
  const Parsed<Replay> replay = loadReplay(out.string());
  ASSERT_TRUE(replay.ok()) << replay.error().toString();
  EXPECT_EQ(replay.value().scene, "/usr/share/cardemo/lot.json");
}

TEST(Recorder, ReportsAnUnwritableFolder) {
  Recorder rec("/nonexistent-cardemo-dir/x.replay", "", 120, 120);
  EXPECT_FALSE(rec.error().empty());
  rec.record(kUp);
  EXPECT_FALSE(rec.finish().empty());
}

TEST(Recorder, KeepsAndNamesALeftoverPart) {
  const fs::path dir = testing::freshTempDir("recorder_test_leftover");
  const fs::path out = dir / "r.replay";
  const std::string leftover = "cardemo-replay 1\nhz 120\n120 U\n";
  std::ofstream(dir / "r.replay.part") << leftover;
  EXPECT_NE(leftoverRecording(out.string()).find("left over"), std::string::npos);
  EXPECT_NE(leftoverRecording(out.string()).find("cardemo replay " + out.string() + ".part"),
            std::string::npos);
  {
    Recorder rec(out.string(), "", 120, 120);
    EXPECT_NE(rec.error().find("left over"), std::string::npos) << rec.error();
    rec.record(kUp);
    EXPECT_FALSE(rec.finish().empty());
  }
  EXPECT_EQ(slurp(dir / "r.replay.part"), leftover) << "a leftover recording must not be touched";
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftoverRecording((dir / "other.replay").string()), "");
}

TEST(Recorder, NamesAPartBeingRecordedByAnotherGame) {
  const fs::path dir = testing::freshTempDir("recorder_test_busy");
  const fs::path out = dir / "r.replay";
  Recorder first(out.string(), "", 120, 120);
  ASSERT_EQ(first.error(), "");
  EXPECT_NE(leftoverRecording(out.string()).find("recording to it right now"), std::string::npos)
      << leftoverRecording(out.string());
  Recorder second(out.string(), "", 120, 120);
  EXPECT_NE(second.error().find("recording to it right now"), std::string::npos) << second.error();
  first.record(kUp);
  EXPECT_EQ(first.finish(), "");
  EXPECT_EQ(leftoverRecording(out.string()), "");
}

// Records `frames` random inputs (flushing every 10 frames) in a child process whose files may not
// grow past `limit_bytes` (RLIMIT_FSIZE, SIGXFSZ ignored as the game does: writes then fail with
// EFBIG, the same path as ENOSPC on a full disk). The child writes its error and durable frame
// count to `report`.
void recordUnderSizeLimit(const fs::path& out, const fs::path& report, rlim_t limit_bytes,
                          const std::vector<InputFrame>& inputs) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit original{};
    if (getrlimit(RLIMIT_FSIZE, &original) != 0) _exit(3);
    rlimit limit = original;
    limit.rlim_cur = limit_bytes;  // the soft limit only, so that it can be lifted again
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(3);
    std::string result;
    {
      Recorder rec(out.string(), "", 120, 10);
      for (const InputFrame& in : inputs) rec.record(in);
      const std::string why = rec.finish();
      result = std::to_string(rec.durableFrames()) + "\n" + why + "\n";
    }
    if (setrlimit(RLIMIT_FSIZE, &original) != 0) _exit(3);
    std::ofstream(report) << result;
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

std::vector<InputFrame> randomInputs(int n, std::uint32_t seed) {
  std::vector<InputFrame> inputs;
  for (int i = 0; i < n; ++i) {
    seed = seed * 1664525u + 1013904223u;
    inputs.push_back(InputFrame::fromBits(static_cast<std::uint8_t>(seed >> 28)));
  }
  return inputs;
}

TEST(Recorder, AFailedWriteKeepsAValidPrefixAndSaysSo) {
  const fs::path dir = testing::freshTempDir("recorder_test_full");
  const fs::path out = dir / "r.replay";
  const std::vector<InputFrame> inputs = randomInputs(1000, 99);
  recordUnderSizeLimit(out, dir / "report.txt", 2000, inputs);
  std::ifstream report(dir / "report.txt");
  std::int64_t durable = -1;
  std::string blank, why;
  report >> durable;
  std::getline(report, blank);
  std::getline(report, why);
  EXPECT_NE(why.find("File too large"), std::string::npos) << why;
  EXPECT_NE(why.find("kept in"), std::string::npos) << why;
  EXPECT_FALSE(fs::exists(out)) << "an incomplete recording must not be published";
  const std::string part = slurp(dir / "r.replay.part");
  EXPECT_LE(part.size(), 2000u);
  const Parsed<Replay> prefix = parseReplay(part, "r.replay.part");
  ASSERT_TRUE(prefix.ok()) << prefix.error().toString();
  EXPECT_EQ(prefix.value().totalFrames(), durable);
  EXPECT_GT(durable, 0);
  EXPECT_EQ(durable % 10, 0) << "the file ends at a flush point";
  std::vector<InputFrame> back;
  for (const InputRun& run : prefix.value().runs) back.insert(back.end(), run.count, run.keys);
  EXPECT_TRUE(std::equal(back.begin(), back.end(), inputs.begin()));
}

TEST(Recorder, NoRoomForTheHeaderLeavesNoFile) {
  const fs::path dir = testing::freshTempDir("recorder_test_noroom");
  const fs::path out = dir / "r.replay";
  recordUnderSizeLimit(out, dir / "report.txt", 8, randomInputs(50, 7));
  const std::string report = slurp(dir / "report.txt");
  EXPECT_NE(report.find("cannot write"), std::string::npos) << report;
  EXPECT_FALSE(fs::exists(dir / "r.replay.part"));
  EXPECT_FALSE(fs::exists(out));
}

// Every write stays inside one 4 KiB page, so a kill between pages cannot cut a line: the file is
// a valid replay at every page boundary, and pads with comment lines where a line would straddle.
TEST(Recorder, NoLineStraddlesAPage) {
  const fs::path dir = testing::freshTempDir("recorder_test_pages");
  const fs::path out = dir / "r.replay";
  {
    Recorder rec(out.string(), "", 120, 37);
    for (const InputFrame& in : randomInputs(5000, 5)) rec.record(in);
  }
  const std::string text = slurp(out);
  ASSERT_GT(text.size(), 4 * 4096u);
  for (std::size_t page = 4096; page < text.size(); page += 4096) {
    EXPECT_EQ(text[page - 1], '\n') << "page ending at byte " << page;
    const Parsed<Replay> prefix = parseReplay(text.substr(0, page), "prefix");
    EXPECT_TRUE(prefix.ok()) << prefix.error().toString();
  }
}

}  // namespace
}  // namespace cardemo
