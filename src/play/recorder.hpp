#pragma once
/// Records the inputs of a live game as a replay file, appended and flushed as it goes.

#include <cstdint>
#include <cstdio>
#include <string>

#include "sim/input_frame.hpp"

namespace cardemo {

/// Writes `cardemo-replay 1` text to `PATH.part` while playing: runs of equal inputs are merged,
/// and the file is flushed at least once per `flush_every_frames` so a killed game loses at most
/// that much. finish() writes the last run (and optional expectation lines), fsyncs and renames the
/// file onto PATH, so PATH is always either absent/old or a complete replay.
class Recorder {
 public:
  /// Starts a recording; `scene_path` is written relative to PATH's folder when possible.
  Recorder(std::string path, const std::string& scene_path, int hz,
           std::int64_t flush_every_frames);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Appends one step's input.
  void record(const InputFrame& input);
  /// Completes the file with `trailer` (e.g. expectation lines) and publishes it. Safe to call
  /// more than once (later calls do nothing). Returns an empty string or what went wrong.
  std::string finish(const std::string& trailer = {});
  /// Empty, or why the recording cannot be written.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// Frames recorded so far.
  [[nodiscard]] std::int64_t frames() const { return frames_; }

 private:
  void writeRun();
  std::string path_;
  std::string part_path_;
  std::FILE* file_ = nullptr;
  InputFrame run_keys_;
  std::int64_t run_length_ = 0;
  std::int64_t frames_ = 0;
  std::int64_t flush_every_ = 120;
  std::int64_t since_flush_ = 0;
  bool finished_ = false;
  std::string error_;
};

}  // namespace cardemo
