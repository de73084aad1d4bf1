// Fuzz target: the replay text parser (src/io/replay_text). Properties: no crash, hang, leak or UB;
// an error names the file and a line inside the input, in one printable line; an accepted replay
// respects the documented limits, and writing it back (formatReplay, what `play --record` writes)
// gives text that parses to the same replay and formats to the same text.

#include "io/replay_text.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"

namespace cardemo::fuzz {
namespace {

constexpr const char* kFile = "fuzz.replay";

void requireValidReplay(const Replay& replay) {
  require(replay.hz >= 1 && replay.hz <= 10000, "hz outside 1..10000");
  std::int64_t total = 0;
  for (const InputRun& run : replay.runs) {
    require(run.count >= 1, "a run of fewer than 1 frame");
    total += run.count;
    require(total <= kMaxReplayFrames, "more frames than kMaxReplayFrames");
  }
  require(total == replay.totalFrames(), "totalFrames() disagrees with the runs");
  if (replay.expect.hash) require(replay.expect.hash->size() == 16, "expect hash not 16 digits");
}

void requireRoundTrip(const Replay& replay) {
  const std::string written = formatReplay(replay);
  const Parsed<Replay> again = parseReplay(written, kFile);
  require(again.ok(), "formatReplay output does not parse: " +
                          (again.ok() ? std::string() : again.error().toString()) + "\n" + written);
  const Replay& r = again.value();
  require(r.scene == replay.scene && r.hz == replay.hz, "scene or hz changed in the round trip");
  require(r.runs.size() == replay.runs.size(), "run count changed in the round trip");
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    require(r.runs[i].count == replay.runs[i].count && r.runs[i].keys == replay.runs[i].keys,
            "run " + std::to_string(i) + " changed in the round trip");
  }
  require(formatReplay(r) == written, "formatting the reparsed replay gives different text");
}

}  // namespace
}  // namespace cardemo::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cardemo;
  const std::string_view text = fuzz::asText(data, size);
  const Parsed<Replay> parsed = parseReplay(text, fuzz::kFile);
  if (!parsed.ok()) {
    fuzz::requireGoodError(parsed.error(), text, fuzz::kFile);
    return 0;
  }
  fuzz::requireValidReplay(parsed.value());
  fuzz::requireRoundTrip(parsed.value());
  return 0;
}
