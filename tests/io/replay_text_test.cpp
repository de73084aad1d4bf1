#include "io/replay_text.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "io_test_util.hpp"

namespace cardemo {
namespace {

using testing::failsAt;
using testing::replaced;

// Line numbers below refer to this text.
constexpr std::string_view kReplay =
    "cardemo-replay 1\n"               // 1
    "# a comment\n"                    // 2
    "scene ../scenes/lot.json\n"       // 3
    "hz 60\n"                          // 4
    "\n"                               // 5
    "240 U\n"                          // 6
    "60 UL   # turning\n"              // 7
    "120 .\n"                          // 8
    "expect frames 420\n"              // 9
    "expect health 85\n"               // 10
    "expect hits 2\n"                  // 11
    "expect hit 100 A1\n"              // 12
    "expect hit 233 kerb #2\n"         // 13
    "expect hash 0123456789abcdef\n";  // 14

Parsed<Replay> parseSampleReplay(std::string_view text) {
  return parseReplay(text, "replays/r.txt");
}

std::string replayWith(std::string_view from, std::string_view to) {
  return replaced(std::string(kReplay), from, to);
}

void expectSameReplay(const Replay& a, const Replay& b) {
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.hz, b.hz);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    EXPECT_EQ(a.runs[i].count, b.runs[i].count);
    EXPECT_EQ(a.runs[i].keys, b.runs[i].keys);
  }
  EXPECT_EQ(a.expect.health, b.expect.health);
  EXPECT_EQ(a.expect.hit_count, b.expect.hit_count);
  EXPECT_EQ(a.expect.hash, b.expect.hash);
  EXPECT_EQ(a.expect.frames, b.expect.frames);
  ASSERT_EQ(a.expect.hits.has_value(), b.expect.hits.has_value());
  if (a.expect.hits) {
    ASSERT_EQ(a.expect.hits->size(), b.expect.hits->size());
    for (std::size_t i = 0; i < a.expect.hits->size(); ++i) {
      EXPECT_EQ((*a.expect.hits)[i].frame, (*b.expect.hits)[i].frame);
      EXPECT_EQ((*a.expect.hits)[i].id, (*b.expect.hits)[i].id);
    }
  }
}

TEST(ReplayText, ParsesAValidReplay) {
  const Parsed<Replay> p = parseSampleReplay(kReplay);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  const Replay& r = p.value();
  EXPECT_EQ(r.scene, "../scenes/lot.json");
  EXPECT_EQ(r.scene_resolved, "replays/../scenes/lot.json");
  EXPECT_EQ(r.hz, 60);
  ASSERT_EQ(r.runs.size(), 3u);
  EXPECT_EQ(r.runs[0].count, 240);
  EXPECT_EQ(r.runs[0].keys, (InputFrame{true, false, false, false}));
  EXPECT_EQ(r.runs[1].keys, (InputFrame{true, false, true, false}));
  EXPECT_EQ(r.runs[2].keys, InputFrame{});
  EXPECT_EQ(r.totalFrames(), 420);
  EXPECT_EQ(r.expect.frames, 420);
  EXPECT_EQ(r.expect.health, 85);
  EXPECT_EQ(r.expect.hit_count, 2);
  ASSERT_TRUE(r.expect.hits.has_value());
  ASSERT_EQ(r.expect.hits->size(), 2u);
  EXPECT_EQ((*r.expect.hits)[0].frame, 100);
  EXPECT_EQ((*r.expect.hits)[0].id, "A1");
  EXPECT_EQ((*r.expect.hits)[1].frame, 233);
  EXPECT_EQ((*r.expect.hits)[1].id, "kerb");
  EXPECT_EQ(r.expect.hash, "0123456789abcdef");
}

TEST(ReplayText, HeaderOnlyIsAZeroFrameReplay) {
  const Parsed<Replay> p = parseSampleReplay("cardemo-replay 1\n");
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().hz, 120);
  EXPECT_TRUE(p.value().runs.empty());
  EXPECT_EQ(p.value().totalFrames(), 0);
  EXPECT_TRUE(p.value().scene.empty());
  EXPECT_TRUE(p.value().scene_resolved.empty());
  EXPECT_FALSE(p.value().expect.hits.has_value());
  EXPECT_TRUE(parseSampleReplay("cardemo-replay 1").ok());  // no final newline
}

TEST(ReplayText, ScenePathResolution) {
  const std::string text = "cardemo-replay 1\nscene ../scenes/lot.json\n";
  EXPECT_EQ(parseReplay(text, "r.txt").value().scene_resolved, "../scenes/lot.json");
  EXPECT_EQ(parseReplay(text, "-").value().scene_resolved, "../scenes/lot.json");
  EXPECT_EQ(parseReplay(text, "/a/b/r.txt").value().scene_resolved, "/a/b/../scenes/lot.json");
  EXPECT_EQ(
      parseReplay("cardemo-replay 1\nscene /abs/lot.json\n", "a/r.txt").value().scene_resolved,
      "/abs/lot.json");
  EXPECT_EQ(parseReplay("cardemo-replay 1\nscene  my lot#1.json  \n", "a/r.txt").value().scene,
            "my lot#1.json");
}

TEST(ReplayText, CrLfLineEndings) {
  std::string text;
  for (const char c : kReplay) text += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Parsed<Replay> p = parseSampleReplay(text);
  ASSERT_TRUE(p.ok()) << p.error().toString();
  expectSameReplay(p.value(), parseSampleReplay(kReplay).value());
}

TEST(ReplayText, ByteOrderMarkIsTolerated) {
  const Parsed<Replay> p = parseSampleReplay("\xEF\xBB\xBF" + std::string(kReplay));
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().totalFrames(), 420);
}

TEST(ReplayText, KeysText) {
  EXPECT_EQ(keysText({}), ".");
  EXPECT_EQ(keysText({true, true, true, true}), "UDLR");
  EXPECT_EQ(keysText({false, false, true, true}), "LR");
  const Parsed<Replay> p = parseSampleReplay("cardemo-replay 1\n1 RLDU\n");
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(keysText(p.value().runs[0].keys), "UDLR");
}

TEST(ReplayText, HandbrakeKeyParsesAndWrites) {
  const Parsed<Replay> p = parseSampleReplay("cardemo-replay 1\n2 HUL\n1 H\n");
  ASSERT_TRUE(p.ok()) << p.error().toString();
  EXPECT_EQ(p.value().runs[0].keys, (InputFrame{true, false, true, false, true}));
  EXPECT_EQ(p.value().runs[1].keys, (InputFrame{false, false, false, false, true}));
  EXPECT_EQ(keysText(p.value().runs[0].keys), "ULH");
  EXPECT_EQ(keysText(p.value().runs[1].keys), "H");
  EXPECT_EQ(p.value().runs[1].keys.bits(), 16);
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\n1 HH\n"), 2, "key H repeated"));
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\n1 h\n"), 2, "use upper-case"));
}

TEST(ReplayText, FormatThenParseRoundTrips) {
  const Replay original = parseSampleReplay(kReplay).value();
  const std::string text = formatReplay(original);
  const Parsed<Replay> again = parseSampleReplay(text);
  ASSERT_TRUE(again.ok()) << again.error().toString() << "\n" << text;
  expectSameReplay(original, again.value());
  EXPECT_EQ(formatReplay(again.value()), text);
}

TEST(ReplayText, RandomReplaysRoundTrip) {
  std::mt19937_64 rng(12345);
  for (int trial = 0; trial < 500; ++trial) {
    Replay r;
    if (rng() % 2) r.scene = "scenes/s" + std::to_string(rng() % 100) + ".json";
    r.hz = 1 + static_cast<int>(rng() % 10000);
    const int runs = static_cast<int>(rng() % 20);
    for (int i = 0; i < runs; ++i) {
      r.runs.push_back({1 + static_cast<std::int64_t>(rng() % 100000),
                        InputFrame::fromBits(static_cast<std::uint8_t>(rng() % 32))});
    }
    if (rng() % 2) r.expect.health = static_cast<int>(rng() % 101);
    if (rng() % 2) r.expect.frames = r.totalFrames();
    if (rng() % 2) r.expect.hash = "00112233445566ff";
    if (rng() % 2) {
      r.expect.hits.emplace();
      std::int64_t frame = 0;
      for (int i = 0; i < 1 + static_cast<int>(rng() % 4); ++i) {
        frame += static_cast<std::int64_t>(rng() % 50);
        r.expect.hits->push_back({frame, "car " + std::to_string(i)});
      }
      if (rng() % 2) r.expect.hit_count = static_cast<std::int64_t>(r.expect.hits->size());
    }
    const Parsed<Replay> p = parseSampleReplay(formatReplay(r));
    ASSERT_TRUE(p.ok()) << p.error().toString();
    expectSameReplay(r, p.value());
  }
}

TEST(ReplayText, EmptyHitListIsWrittenAsZeroHits) {
  Replay r;
  r.expect.hits.emplace();
  const Parsed<Replay> p = parseSampleReplay(formatReplay(r));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value().expect.hit_count, 0);
}

// --- malformed input, one class per test ---

TEST(ReplayTextErrors, EmptyFile) {
  EXPECT_TRUE(failsAt(parseSampleReplay(""), 1, "empty replay file"));
  EXPECT_TRUE(failsAt(parseSampleReplay("\n\n"), 1, "empty replay file"));
}

TEST(ReplayTextErrors, BadHeader) {
  EXPECT_TRUE(
      failsAt(parseSampleReplay("cardemo-replay 2\n10 U\n"), 1, "unsupported replay version"));
  EXPECT_TRUE(failsAt(parseSampleReplay("hello\n"), 1, "line 1 must be \"cardemo-replay 1\""));
  EXPECT_TRUE(failsAt(parseSampleReplay("# comment\ncardemo-replay 1\n"), 1, "line 1 must be"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay("cardemo-replay 1 extra\n"), 1, "unsupported replay version"));
}

TEST(ReplayTextErrors, GarbageBytes) {
  EXPECT_TRUE(failsAt(parseSampleReplay(std::string_view("\xff\xfe\x00\x01garbage", 11)), 1,
                      "control character"));
  EXPECT_TRUE(failsAt(parseSampleReplay("\x89PNG\r\n"), 1, "not a replay file"));
}

TEST(ReplayTextErrors, NulByteInALine) {
  std::string text = replayWith("120 .", "120 .");
  text[text.find("120 .") + 3] = '\0';
  EXPECT_TRUE(failsAt(parseSampleReplay(text), 8, "control character \"\\x00\""));
}

TEST(ReplayTextErrors, LineBreaksControlsAndCommentsInOnePass) {
  // One '\r' before the line break is part of the break; any other, even in a comment, is not.
  EXPECT_TRUE(parseSampleReplay("cardemo-replay 1\r\n10 U\r\n5 .\r").ok());
  EXPECT_TRUE(
      failsAt(parseSampleReplay("cardemo-replay 1\n10 U\r\r\n"), 2, "control character \"\\x0d\""));
  EXPECT_TRUE(
      failsAt(parseSampleReplay("cardemo-replay 1\n10 U # a\rb\n"), 2, "control character"));
  // The first control byte is the one named; a tab is not one.
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\n10\tU\x01\x02\n"), 2, "\"\\x01\""));
  // `#` starts a comment only at the start or after a blank; the first such one counts.
  const Parsed<Replay> p = parseSampleReplay("cardemo-replay 1\n\t10 U\t# x # y\n# 5 D\n");
  ASSERT_TRUE(p.ok());
  ASSERT_EQ(p.value().runs.size(), 1u);
  EXPECT_EQ(p.value().runs[0].count, 10);
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\n10 U#x\n"), 2, "unknown key \"#\""));
}

TEST(ReplayTextErrors, CountOverflow) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "99999999999999999999 U")), 6,
                      "exceeds the limit"));
}

TEST(ReplayTextErrors, CountAboveCap) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "100000001 U")), 6,
                      "exceeds the limit of 100000000"));
  EXPECT_TRUE(
      parseSampleReplay(replayWith("240 U", "99999820 U")).ok());  // exactly the cap in total
}

TEST(ReplayTextErrors, TotalFramesOverCap) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "60000000 U\n60000000 D")), 7,
                      "replay exceeds the limit of 100000000 frames in total"));
}

TEST(ReplayTextErrors, CountZeroOrNegative) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "0 U")), 6, "count must be >= 1"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("240 U", "-5 U")), 6, "count: expected a whole number"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("240 U", "+5 U")), 6, "count: expected a whole number"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "2.5 U")), 6,
                      "count: expected a whole number"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("240 U", "240U")), 6, "count: expected a whole number"));
}

TEST(ReplayTextErrors, OneMegabyteLine) {
  const std::string big(1 << 20, 'x');
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("# a comment", "# " + big)), 2,
                      "line longer than 4096 bytes"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("120 .", "120 " + big)), 8,
                      "line longer than 4096 bytes"));
  // A single line of a megabyte without any newline at all.
  EXPECT_TRUE(
      failsAt(parseSampleReplay(std::string(1 << 20, 'c')), 1, "line longer than 4096 bytes"));
}

TEST(ReplayTextErrors, LineOfExactly4096BytesIsAccepted) {
  const std::string comment = "#" + std::string(4095, 'c');
  EXPECT_TRUE(parseSampleReplay(replayWith("# a comment", comment)).ok());
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("# a comment", comment + "c")), 2, "line longer"));
}

TEST(ReplayTextErrors, UnknownKeyLetter) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "240 X")), 6, "unknown key \"X\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "240 U?")), 6, "unknown key \"?\""));
}

TEST(ReplayTextErrors, LowercaseKeys) {
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("240 U", "240 uu")), 6, "use upper-case U, D, L, R"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("60 UL", "60 Ul")), 7, "use upper-case"));
}

TEST(ReplayTextErrors, RepeatedKey) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("240 U", "240 UU")), 6, "key U repeated"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("60 UL", "60 LUL")), 7, "key L repeated"));
}

TEST(ReplayTextErrors, DotCombinedWithKeys) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("120 .", "120 .U")), 8, "cannot be combined"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("120 .", "120 ..")), 8, "cannot be combined"));
}

TEST(ReplayTextErrors, MissingOrExtraKeys) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("120 .", "120")), 8, "keys missing"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("120 .", "120 . U")), 8,
                      "unexpected \"U\" after the keys"));
}

TEST(ReplayTextErrors, BadHz) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz 0")), 4,
                      "hz: expected a whole number from 1 to 10000"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz 10001")), 4,
                      "from 1 to 10000, found \"10001\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz 1.5")), 4, "found \"1.5\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz")), 4, "found \"\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz -1")), 4, "hz: expected"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "hz 60 60")), 4, "hz: expected"));
  EXPECT_TRUE(parseSampleReplay(replayWith("hz 60", "hz 10000")).ok());
  EXPECT_TRUE(parseSampleReplay(replayWith("hz 60", "hz 1")).ok());
}

TEST(ReplayTextErrors, DuplicateDirectives) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60\n", "hz 60\nhz 30\n")), 5,
                      "duplicate \"hz\" line (first on line 4)"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60\n", "hz 60\nscene b.json\n")), 5,
                      "duplicate \"scene\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(std::string(kReplay) + "expect health 3\n"), 15,
                      "duplicate \"expect health\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(std::string(kReplay) + "expect hash 0123456789abcdef\n"),
                      15, "duplicate \"expect hash\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(std::string(kReplay) + "expect frames 1\n"), 15,
                      "duplicate \"expect frames\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(std::string(kReplay) + "expect hits 2\n"), 15,
                      "duplicate \"expect hits\""));
}

TEST(ReplayTextErrors, MissingScenePath) {
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("scene ../scenes/lot.json", "scene   # nothing")), 3,
              "scene: missing path"));
}

TEST(ReplayTextErrors, UnknownDirective) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("hz 60", "speed 60")), 4,
                      "unknown directive \"speed\""));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("hz 60", "HZ 60")), 4, "unknown directive \"HZ\""));
}

TEST(ReplayTextErrors, BadExpectHash) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("0123456789abcdef", "0123")), 14,
                      "16 lower-case hex digits"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("0123456789abcdef", "0123456789ABCDEF")), 14,
                      "lower-case hex"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("0123456789abcdef", "0123456789abcdefa")), 14, "hex"));
  EXPECT_TRUE(
      failsAt(parseSampleReplay(replayWith("0123456789abcdef", "0123456789abcdeg")), 14, "hex"));
}

TEST(ReplayTextErrors, BadExpectNumbers) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect health 85", "expect health x")), 10,
                      "expect health: expected a whole number from 0 to 1000000"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect health 85", "expect health -1")), 10,
                      "expect health"));
  EXPECT_TRUE(failsAt(
      parseSampleReplay(replayWith("expect frames 420", "expect frames 99999999999999999999")), 9,
      "expect frames: expected a whole number"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect hits 2", "expect hits")), 11,
                      "expect hits: expected"));
}

TEST(ReplayTextErrors, BadExpectHit) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect hit 100 A1", "expect hit 100")), 12,
                      "missing id"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect hit 100 A1", "expect hit x A1")), 12,
                      "expect hit: frame: expected a whole number"));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect hit 100 A1", "expect hit 300 A1")), 13,
                      "list hits in frame order"));
}

TEST(ReplayTextErrors, HitCountDisagreesWithHitLines) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect hits 2", "expect hits 3")), 11,
                      "expect hits 3 but 2 \"expect hit\" lines"));
}

TEST(ReplayTextErrors, UnknownExpectation) {
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect health 85", "expect speed 85")), 10,
                      "unknown expectation \"speed\""));
  EXPECT_TRUE(failsAt(parseSampleReplay(replayWith("expect health 85", "expect")), 10,
                      "unknown expectation \"\""));
}

TEST(ReplayTextErrors, MissingFileReportsLineZero) {
  const Parsed<Replay> p = loadReplay("/nonexistent/cardemo/r.txt");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().line, 0);
  EXPECT_NE(p.error().toString().find("/nonexistent/cardemo/r.txt: cannot open"),
            std::string::npos);
}

// --- expect parked ---

TEST(ReplayTextParked, FrameAndNeverParseAndRoundTrip) {
  const Parsed<Replay> at = parseSampleReplay("cardemo-replay 1\n10 U\nexpect parked 812\n");
  ASSERT_TRUE(at.ok()) << at.error().toString();
  ASSERT_TRUE(at.value().expect.parked.has_value());
  EXPECT_EQ(*at.value().expect.parked, 812);
  EXPECT_NE(formatReplay(at.value()).find("expect parked 812\n"), std::string::npos);

  const Parsed<Replay> never = parseSampleReplay("cardemo-replay 1\nexpect parked never\n");
  ASSERT_TRUE(never.ok()) << never.error().toString();
  ASSERT_TRUE(never.value().expect.parked.has_value());
  EXPECT_FALSE(never.value().expect.parked->has_value());
  const std::string text = formatReplay(never.value());
  EXPECT_NE(text.find("expect parked never\n"), std::string::npos);
  EXPECT_TRUE(parseSampleReplay(text).value().expect.parked.has_value());

  EXPECT_FALSE(parseSampleReplay("cardemo-replay 1\n").value().expect.parked.has_value());
  EXPECT_EQ(formatExpectations(ReplayExpectations{}).find("parked"), std::string::npos);
}

TEST(ReplayTextParkedErrors, BadValueAndDuplicate) {
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\nexpect parked soon\n"), 2,
                      "expect parked: expected a frame from 0 to 100000000 or \"never\""));
  EXPECT_TRUE(
      failsAt(parseSampleReplay("cardemo-replay 1\nexpect parked -1\n"), 2, "expect parked:"));
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\nexpect parked\n"), 2, "expect parked:"));
  EXPECT_TRUE(failsAt(parseSampleReplay("cardemo-replay 1\nexpect parked 5\nexpect parked never\n"),
                      3, "duplicate \"expect parked\" line (first on line 2)"));
}

}  // namespace
}  // namespace cardemo
