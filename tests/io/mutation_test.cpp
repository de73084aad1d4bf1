// Seeded random byte mutations of valid inputs: every parser must return a value or an error with
// a line >= 1, and never crash or hang.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <utility>

#include "../support/mutate_text.hpp"
#include "io/pair_csv.hpp"
#include "io/replay_text.hpp"
#include "io/scene_json.hpp"

namespace cardemo {
namespace {

constexpr std::string_view kMutatedScene = R"({
  "format": "cardemo-scene/1",
  "name": "lot",
  "bounds": {"min": [-60, -40], "max": [60, 40]},
  "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8, "health": 100},
  "parked": [
    {"id": "A1", "x": 10, "y": 5, "heading_deg": 90, "length": 4.5, "width": 1.8},
    {"id": "A2", "x": -10, "y": 5, "heading_deg": 30, "length": 4, "width": 2}
  ],
  "obstacles": [{"id": "kerb", "points": [[0, 0], [0, 1], [3, 1], [3, 0]]}]
}
)";

constexpr std::string_view kMutatedReplay =
    "cardemo-replay 1\nscene ../lot.json\nhz 120\n# c\n240 U\n60 UL # t\n120 .\n"
    "expect health 85\nexpect hits 1\nexpect hit 233 A1\nexpect hash 9f3c0e1d2b4a6c58\n";

constexpr std::string_view kPairs =
    "ax,ay,a_heading_deg,a_length,a_width,bx,by,b_heading_deg,b_length,b_width\n"
    "0,0,0,4,2,3,1,90,4,2\n# c\n1.5,-2,45,1,1,0,0,0,1,1\n";

constexpr std::string_view kPairs3 =
    "0,0,0,1,0,0,0,2,4,6,1,2,3,1,0,0,0,1,1,1\n5,5,5,0.7,0.1,0.2,0.7,1,1,1,0,0,0,1,0,0,0,1,1,1\n";

// The replay, scene and pair readers' mutations: up to four edits, replay keys among the bytes.
std::string mutate(std::string s, std::mt19937_64& rng) {
  static constexpr test::TextMutation kHow{"{}[]\",:.-+eE0123456789#\n\r\t \\UDLR", 4, 16, false};
  return test::mutateText(std::move(s), rng, kHow);
}

template <typename T, typename Parse>
void fuzz(std::string_view valid, std::uint64_t seed, Parse parse) {
  std::mt19937_64 rng(seed);
  int ok = 0;
  for (int i = 0; i < 10000; ++i) {
    const std::string text = mutate(std::string(valid), rng);
    const Parsed<T> p = parse(text);
    if (p.ok()) {
      ++ok;
      continue;
    }
    ASSERT_GE(p.error().line, 1) << p.error().toString() << "\ninput:\n" << text;
    ASSERT_FALSE(p.error().message.empty());
    ASSERT_EQ(p.error().file, "f");
  }
  EXPECT_GT(ok, 0);  // some mutations (inside names, numbers) stay valid
}

TEST(Mutation, SceneParserNeverCrashes) {
  fuzz<Scene>(kMutatedScene, 1, [](std::string_view t) { return parseScene(t, "f"); });
}

TEST(Mutation, ReplayParserNeverCrashes) {
  fuzz<Replay>(kMutatedReplay, 2, [](std::string_view t) { return parseReplay(t, "f"); });
}

TEST(Mutation, PairParsersNeverCrash) {
  fuzz<std::vector<PairRow2>>(kPairs, 3, [](std::string_view t) { return parsePairs2(t, "f"); });
  fuzz<std::vector<PairRow3>>(kPairs3, 4, [](std::string_view t) { return parsePairs3(t, "f"); });
}

}  // namespace
}  // namespace cardemo
