#pragma once
/// Replay files (`cardemo-replay 1`): parse, expectations, and writing (for --record).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_error.hpp"
#include "sim/input_frame.hpp"

namespace cardemo {

/// COUNT frames holding the same keys.
struct InputRun {
  std::int64_t count = 1;  ///< >= 1.
  InputFrame keys;         ///< Keys held.
};

/// An expected hit (`expect hit FRAME ID`).
struct ExpectedHit {
  std::int64_t frame = 0;  ///< Frame of first contact.
  std::string id;          ///< Collider id.
};

/// Expectation lines of a replay; each is optional.
struct ReplayExpectations {
  std::optional<int> health;                     ///< `expect health H`
  std::optional<std::int64_t> hit_count;         ///< `expect hits N`
  std::optional<std::vector<ExpectedHit>> hits;  ///< `expect hit F ID` lines, in order
  std::optional<std::string> hash;               ///< `expect hash HEX16`
  std::optional<std::int64_t> frames;            ///< `expect frames N`
  /// `expect parked FRAME` (inner value) or `expect parked never` (inner nullopt).
  std::optional<std::optional<std::int64_t>> parked;
};

/// A parsed replay.
struct Replay {
  std::string scene;  ///< Scene path as written (relative to the replay's folder); may be empty.
  std::string scene_resolved;  ///< Scene path resolved against the replay file's folder.
  int scene_line = 0;          ///< Line of the `scene` line (0 when there is none).
  int hz = 120;                ///< Fixed steps per second, 1..10000.
  std::vector<InputRun> runs;  ///< Inputs in order.
  ReplayExpectations expect;   ///< Optional expectations.

  /// Total frames of input.
  [[nodiscard]] std::int64_t totalFrames() const;
};

/// Limits that keep hostile replays from hanging the program.
inline constexpr std::int64_t kMaxReplayFrames = 100'000'000;
/// Longest accepted line, bytes.
inline constexpr std::size_t kMaxLineBytes = 4096;

/// Parses replay text; `filename` resolves the scene path and labels errors.
[[nodiscard]] Parsed<Replay> parseReplay(std::string_view text, const std::string& filename);

/// Reads and parses a replay file.
[[nodiscard]] Parsed<Replay> loadReplay(const std::string& path);

/// Formats keys as the replay writes them: `.` or letters in the order U D L R H. The only writer
/// of key text: every replay line goes through it (at most 5 characters: no allocation).
[[nodiscard]] std::string keysText(const InputFrame& keys);

/// Appends the input line `COUNT KEYS\n`; allocates only when `out` lacks the capacity.
void appendInputLine(std::string& out, std::int64_t count, const InputFrame& keys);

/// The lines before the inputs: `cardemo-replay 1`, `scene SCENE` (left out when empty), `hz HZ`.
[[nodiscard]] std::string replayHeaderText(const std::string& scene, int hz);

/// The expectation lines (`expect ...`) for `expectations`, one per line, in a fixed order.
[[nodiscard]] std::string formatExpectations(const ReplayExpectations& expectations);

/// Serialises a replay (header, scene, hz, runs, then expectations), parseable by parseReplay.
[[nodiscard]] std::string formatReplay(const Replay& replay);

}  // namespace cardemo
