// The one writer of replay key text (keysText, appendInputLine, replayHeaderText): every one of
// the 32 key sets written and parsed back, alone and in a whole replay.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/replay_text.hpp"

namespace cardemo {
namespace {

InputFrame keySet(int bits) {
  return InputFrame::fromBits(static_cast<std::uint8_t>(bits));
}

TEST(ReplayKeys, EveryKeySetParsesBackToItself) {
  for (int bits = 0; bits < 32; ++bits) {
    const InputFrame keys = keySet(bits);
    const std::string text = keysText(keys);
    SCOPED_TRACE(text);
    // `.` alone for no keys, else each held key once, in the order U D L R H.
    EXPECT_EQ(text == ".", bits == 0);
    EXPECT_EQ(text.size(), bits == 0 ? 1u : static_cast<std::size_t>(__builtin_popcount(bits)));
    EXPECT_TRUE(std::is_sorted(text.begin(), text.end(), [](char a, char b) {
      return std::string_view("UDLRH").find(a) < std::string_view("UDLRH").find(b);
    }));
    std::string line;
    appendInputLine(line, 7, keys);
    EXPECT_EQ(line, "7 " + text + "\n");
    const Parsed<Replay> back = parseReplay(replayHeaderText("", 120) + line, "keys.replay");
    ASSERT_TRUE(back.ok()) << back.error().toString();
    ASSERT_EQ(back.value().runs.size(), 1u);
    EXPECT_EQ(back.value().runs[0].count, 7);
    EXPECT_EQ(back.value().runs[0].keys, keys);
  }
}

TEST(ReplayKeys, AWholeReplayOfAllKeySetsRoundTrips) {
  Replay replay;
  replay.scene = "../scenes/parking-lot.json";
  replay.hz = 60;
  for (int bits = 0; bits < 32; ++bits) {
    replay.runs.push_back({kMaxReplayFrames / 64 - bits, keySet(31 - bits)});
  }
  const std::string text = formatReplay(replay);
  EXPECT_EQ(text.rfind("cardemo-replay 1\nscene ../scenes/parking-lot.json\nhz 60\n", 0), 0u);
  const Parsed<Replay> back = parseReplay(text, "all.replay");
  ASSERT_TRUE(back.ok()) << back.error().toString();
  EXPECT_EQ(back.value().scene, replay.scene);
  EXPECT_EQ(back.value().hz, 60);
  ASSERT_EQ(back.value().runs.size(), replay.runs.size());
  for (std::size_t i = 0; i < replay.runs.size(); ++i) {
    EXPECT_EQ(back.value().runs[i].count, replay.runs[i].count) << i;
    EXPECT_EQ(back.value().runs[i].keys, replay.runs[i].keys) << i;
  }
  EXPECT_EQ(formatReplay(back.value()), text);
}

TEST(ReplayKeys, HeaderLeavesOutAnEmptyScene) {
  EXPECT_EQ(replayHeaderText("", 120), "cardemo-replay 1\nhz 120\n");
  EXPECT_EQ(replayHeaderText("a b.json", 7), "cardemo-replay 1\nscene a b.json\nhz 7\n");
}

TEST(ReplayKeys, AppendingUsesTheCapacityThere) {
  std::string out;
  out.reserve(64);
  const char* const before = out.data();
  appendInputLine(out, kMaxReplayFrames, keySet(31));
  EXPECT_EQ(out, "100000000 UDLRH\n");
  EXPECT_EQ(out.data(), before) << "no reallocation while recording";
}

}  // namespace
}  // namespace cardemo
