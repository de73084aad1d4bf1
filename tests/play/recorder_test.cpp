// Recorder: merged runs, periodic flushes visible before finish, atomic publish, round trip.

#include "play/recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "io/replay_text.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("cardemo_recorder_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

const InputFrame kUp{true, false, false, false};
const InputFrame kUpLeft{true, false, true, false};
const InputFrame kNone{};

TEST(Recorder, MergesRunsAndPublishesOnFinish) {
  const fs::path dir = tempDir("merge");
  const fs::path out = dir / "drive.replay";
  {
    Recorder rec(out.string(), (dir / "lot.json").string(), 120, 1000);
    for (int i = 0; i < 5; ++i) rec.record(kUp);
    for (int i = 0; i < 3; ++i) rec.record(kUpLeft);
    rec.record(kNone);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::exists(dir / "drive.replay.part"));
    EXPECT_EQ(rec.frames(), 9);
    EXPECT_EQ(rec.finish("expect health 100\n"), "");
    EXPECT_EQ(rec.finish(), "");  // idempotent
  }
  EXPECT_FALSE(fs::exists(dir / "drive.replay.part"));
  const std::string text = slurp(out);
  EXPECT_EQ(text,
            "cardemo-replay 1\nscene lot.json\nhz 120\n# frames  keys\n5 U\n3 UL\n1 .\n"
            "expect health 100\n");
}

TEST(Recorder, FlushesPeriodicallyAsAValidPrefix) {
  const fs::path dir = tempDir("flush");
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
  const fs::path dir = tempDir("roundtrip");
  const fs::path out = dir / "sub" / "r.replay";
  fs::create_directories(out.parent_path());
  std::vector<InputFrame> inputs;
  std::uint32_t seed = 12345;
  InputFrame current;
  for (int i = 0; i < 5000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    if ((seed >> 24) < 20)
      current = InputFrame::fromBits(static_cast<std::uint8_t>(seed >> 8 & 15));
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
  const fs::path dir = tempDir("absolute");
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

}  // namespace
}  // namespace cardemo
