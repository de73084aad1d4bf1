#pragma once
/// Records the inputs of a live game as a replay file, appended and flushed as it goes.

#include <cstdint>
#include <memory>
#include <string>

#include "sim/input_frame.hpp"

namespace cardemo {

class DurableFile;

/// Writes `cardemo-replay 1` text to `PATH.part` while playing: runs of equal inputs are merged,
/// and every `flush_every_frames` frames what was recorded is written and fsynced, so a killed
/// game loses at most that much and PATH.part is always a valid replay of the frames before.
/// finish() writes the last run (and optional expectation lines), fsyncs and renames the file onto
/// PATH, so PATH is always either absent/old or a complete replay.
///
/// PATH.part is created exclusively and locked (flock) while recording: a PATH.part that already
/// exists is never overwritten; it is either another game's, still recording, or left over from
/// a game that was killed. Each write(2) stays within one 4 KiB page of the file (a comment line
/// pads to the page end when a chunk would straddle one), because Linux copies a write a page at
/// a time and may stop between pages when the process is killed: a kill can then never cut a
/// line in half. After a failed write (disk full, file too large) the file is truncated back to
/// what was last written and fsynced, and recording stops there.
class Recorder {
 public:
  /// Starts a recording; `scene_path` is written relative to PATH's folder when possible. On
  /// failure error() says why (and nothing is recorded).
  Recorder(std::string path, const std::string& scene_path, int hz,
           std::int64_t flush_every_frames);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Appends one step's input (no allocation, no system call except at flush points).
  void record(const InputFrame& input);
  /// Completes the file with `trailer` (e.g. expectation lines) and publishes it. Safe to call
  /// more than once (later calls do nothing). Returns an empty string or what went wrong.
  std::string finish(const std::string& trailer = {});
  /// Empty, or why the recording cannot be (or could not all be) written.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// Frames recorded so far.
  [[nodiscard]] std::int64_t frames() const { return frames_; }
  /// Frames written and fsynced to PATH.part so far.
  [[nodiscard]] std::int64_t durableFrames() const { return durable_frames_; }

 private:
  void writeRun();
  bool flushPending();
  void fail();
  std::string path_;
  std::string part_path_;
  std::unique_ptr<DurableFile> file_;  // PATH.part while recording (io/durable_file)
  std::string pending_;                // lines not yet written (capacity reserved up front)
  InputFrame run_keys_;
  std::int64_t run_length_ = 0;
  std::int64_t frames_ = 0;
  std::int64_t durable_frames_ = 0;
  std::int64_t written_bytes_ = 0;  // bytes written to the file
  std::int64_t durable_bytes_ = 0;  // bytes written and fsynced
  std::int64_t flush_every_ = 120;
  std::int64_t since_flush_ = 0;
  bool finished_ = false;
  std::string error_;
};

/// Empty when PATH.part is absent; otherwise one sentence for the user: PATH.part is being
/// written by another running game, or it is left over from a game that did not finish (then it
/// says how to replay it and that it will not be overwritten).
[[nodiscard]] std::string leftoverRecording(const std::string& path);

}  // namespace cardemo
