#include "play/recorder.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>
#include <utility>

#include "io/durable_file.hpp"
#include "io/replay_text.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

// Linux copies a write(2) into the page cache one page at a time and checks for a fatal signal
// between pages (generic_perform_write), so a write that stays inside one page is never cut.
constexpr std::int64_t kPage = 4096;

// The scene as the replay should name it: relative to the replay's folder, so the pair can move
// together; absolute when the two share no folder but the root (a relative path would not help).
std::string sceneRelativeTo(const std::string& replay_path, const std::string& scene_path) {
  std::error_code ec;
  const fs::path folder =
      fs::weakly_canonical(fs::absolute(fs::path(replay_path), ec), ec).parent_path();
  const fs::path scene = fs::weakly_canonical(fs::absolute(fs::path(scene_path), ec), ec);
  if (ec) return scene_path;
  const fs::path rel = scene.lexically_relative(folder);
  int ups = 0;
  for (const fs::path& part : rel) ups += part == ".." ? 1 : 0;
  int depth = 0;
  for (const fs::path& part : folder.relative_path()) depth += part.empty() ? 0 : 1;
  if (rel.empty() || ups >= depth) return scene.generic_string();
  return rel.generic_string();
}

}  // namespace

std::string leftoverRecording(const std::string& path) {
  const std::string part = path + ".part";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(part, ec))) return {};
  if (lockedByAnotherProcess(part)) {
    return part + ": another cardemo is recording to it right now; record to another file";
  }
  return part +
         ": left over from a recording that did not finish (the game was killed); it replays "
         "all but at most its last second with `cardemo replay " +
         part + "`; it is kept: move or delete it to record to " + path + " again";
}

Recorder::Recorder(std::string path, const std::string& scene_path, int hz,
                   std::int64_t flush_every_frames)
    : path_(std::move(path)),
      part_path_(path_ + ".part"),
      flush_every_(flush_every_frames < 1 ? 1 : flush_every_frames) {
  // Never truncate an existing PATH.part: it is another game's, or a killed game's recording.
  file_ = std::make_unique<DurableFile>(part_path_, DurableFile::Existing::kRefuse);
  if (!file_->isOpen()) {
    if (file_->errorNumber() == EEXIST) error_ = leftoverRecording(path_);
    if (error_.empty()) error_ = file_->error();
    file_.reset();
    return;
  }
  // Other games (and `cardemo play` itself, before it opens a window) see the lock.
  (void)file_->tryLock();
  // The longest line is "100000000 UDLRH\n": 32 bytes per run is ample.
  pending_.reserve(static_cast<std::size_t>(std::min<std::int64_t>(flush_every_, 1 << 15)) * 32 +
                   2 * kPage);
  // The column comment helps a reader; formatReplay leaves it out.
  pending_ = replayHeaderText(
                 scene_path.empty() ? std::string() : sceneRelativeTo(path_, scene_path), hz) +
             "# frames  keys\n";
  (void)flushPending();
}

Recorder::~Recorder() {
  (void)finish();
}

void Recorder::fail() {
  error_ = file_->error();
  if (written_bytes_ == durable_bytes_ && durable_bytes_ == 0) {
    // Not even the header is on disk: leave no file that would not parse.
    file_->discard();
  } else {
    // Back to the last complete, fsynced state: a valid replay of durable_frames_ frames.
    (void)file_->truncate(durable_bytes_);
    (void)file_->close();
    error_ += "; recording stopped, its first " + std::to_string(durable_frames_) +
              " frames are kept in " + part_path_;
  }
  file_.reset();
}

void Recorder::writeRun() {
  if (run_length_ == 0) return;
  appendInputLine(pending_, run_length_, run_keys_);
  run_length_ = 0;
}

bool Recorder::flushPending() {
  if (!file_) return false;
  std::size_t start = 0;
  while (start < pending_.size()) {
    const auto room = static_cast<std::size_t>(kPage - written_bytes_ % kPage);
    // The whole lines from `start` that fit before the page ends.
    std::size_t end = start;
    for (std::size_t nl = pending_.find('\n', start);
         nl != std::string::npos && nl + 1 - start <= room; nl = pending_.find('\n', nl + 1)) {
      end = nl + 1;
    }
    if (end == start) {
      // The next line would straddle the page end: fill the page with a comment line instead.
      char pad[kPage];
      std::memset(pad, ' ', room);
      pad[0] = room > 1 ? '#' : '\n';
      pad[room - 1] = '\n';
      if (!file_->append(std::string_view(pad, room))) {
        fail();
        return false;
      }
      written_bytes_ += static_cast<std::int64_t>(room);
      continue;
    }
    if (!file_->append(std::string_view(pending_).substr(start, end - start))) {
      fail();
      return false;
    }
    written_bytes_ += static_cast<std::int64_t>(end - start);
    start = end;
  }
  pending_.clear();
  if (!file_->sync()) {
    fail();
    return false;
  }
  durable_bytes_ = written_bytes_;
  durable_frames_ = frames_ - run_length_;
  return true;
}

void Recorder::record(const InputFrame& input) {
  if (finished_ || !file_) return;
  if (run_length_ > 0 && !(input == run_keys_)) writeRun();
  run_keys_ = input;
  ++run_length_;
  ++frames_;
  if (++since_flush_ >= flush_every_) {
    // A run is split at flush points so the file on disk always ends at the current frame.
    writeRun();
    (void)flushPending();
    since_flush_ = 0;
  }
}

std::string Recorder::finish(const std::string& trailer) {
  if (finished_) return error_;
  finished_ = true;
  if (!file_) return error_;
  writeRun();
  if (!trailer.empty()) {
    pending_ += trailer;
    if (trailer.back() != '\n') pending_ += '\n';
  }
  if (!flushPending()) return error_;
  if (!file_->publishAs(path_)) {
    error_ = file_->error();
    if (!file_->published()) error_ += "; the recording is complete in " + part_path_;
  }
  file_.reset();
  return error_;
}

}  // namespace cardemo
