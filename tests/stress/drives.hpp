#pragma once
/// Input streams for the stress tests: the bundled replays' inputs and seeded random drives.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "io/replay_text.hpp"
#include "sim/input_frame.hpp"

namespace cardemo::stress {

/// The bundled replays (assets/replays), by file name without extension.
inline const std::vector<std::string>& bundledReplays() {
  static const std::vector<std::string> names{"clean",     "demo",      "garage",  "head-on",
                                              "highspeed", "large-lot", "reverse", "scrape"};
  return names;
}

/// Path of a file under the repository's assets/ folder.
inline std::string assetPath(const std::string& relative) {
  return std::string(CARDEMO_SOURCE_DIR) + "/assets/" + relative;
}

/// Every frame of a replay's inputs, in order.
inline std::vector<InputFrame> framesOf(const Replay& replay) {
  std::vector<InputFrame> out;
  for (const InputRun& run : replay.runs) out.insert(out.end(), run.count, run.keys);
  return out;
}

/// A seeded random drive: segments of 10 to 240 frames, each holding a random key set (throttle
/// twice as likely as not, so the car gets somewhere).
inline std::vector<InputFrame> randomDrive(std::uint64_t seed, std::int64_t frames) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> length(10, 240);
  std::uniform_int_distribution<int> keys(0, 15);
  std::vector<InputFrame> out;
  out.reserve(static_cast<std::size_t>(frames));
  while (static_cast<std::int64_t>(out.size()) < frames) {
    InputFrame in = InputFrame::fromBits(static_cast<std::uint8_t>(keys(rng)));
    if (!in.up && !in.down && keys(rng) < 8) in.up = true;
    for (int i = length(rng); i > 0 && static_cast<std::int64_t>(out.size()) < frames; --i) {
      out.push_back(in);
    }
  }
  return out;
}

}  // namespace cardemo::stress
