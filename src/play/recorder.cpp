#include "play/recorder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

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

std::string osError(const std::string& what, const std::string& path, int err) {
  return path + ": cannot " + what + ": " + std::strerror(err);
}

bool writeAll(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) return false;
    if (w == 0) {
      errno = ENOSPC;
      return false;
    }
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// A rename is durable once the folder holding it is fsynced.
void fsyncFolderOf(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

bool lockedByAnotherProcess(const std::string& part) {
  const int fd = ::open(part.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return locked;
}

}  // namespace

std::string leftoverRecording(const std::string& path) {
  const std::string part = path + ".part";
  struct stat st {};
  if (::lstat(part.c_str(), &st) != 0) return {};
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
  fd_ = ::open(part_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int err = errno;
    error_ = err == EEXIST ? leftoverRecording(path_) : osError("create", part_path_, err);
    if (error_.empty()) error_ = osError("create", part_path_, err);
    return;
  }
  // Other games (and `cardemo play` itself, before it opens a window) see the lock.
  (void)::flock(fd_, LOCK_EX | LOCK_NB);
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

void Recorder::fail(const std::string& what) {
  const int err = errno;
  error_ = osError(what, part_path_, err);
  if (written_bytes_ == durable_bytes_ && durable_bytes_ == 0) {
    // Not even the header is on disk: leave no file that would not parse.
    ::close(fd_);
    ::unlink(part_path_.c_str());
  } else {
    // Back to the last complete, fsynced state: a valid replay of durable_frames_ frames.
    (void)::ftruncate(fd_, durable_bytes_);
    (void)::fsync(fd_);
    ::close(fd_);
    error_ += "; recording stopped, its first " + std::to_string(durable_frames_) +
              " frames are kept in " + part_path_;
  }
  fd_ = -1;
}

void Recorder::writeRun() {
  if (run_length_ == 0) return;
  appendInputLine(pending_, run_length_, run_keys_);
  run_length_ = 0;
}

bool Recorder::flushPending() {
  if (fd_ < 0) return false;
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
      if (!writeAll(fd_, pad, room)) {
        fail("write");
        return false;
      }
      written_bytes_ += static_cast<std::int64_t>(room);
      continue;
    }
    if (!writeAll(fd_, pending_.data() + start, end - start)) {
      fail("write");
      return false;
    }
    written_bytes_ += static_cast<std::int64_t>(end - start);
    start = end;
  }
  pending_.clear();
  if (::fsync(fd_) != 0) {
    fail("write");
    return false;
  }
  durable_bytes_ = written_bytes_;
  durable_frames_ = frames_ - run_length_;
  return true;
}

void Recorder::record(const InputFrame& input) {
  if (finished_ || fd_ < 0) return;
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
  if (fd_ < 0) return error_;
  writeRun();
  if (!trailer.empty()) {
    pending_ += trailer;
    if (trailer.back() != '\n') pending_ += '\n';
  }
  if (!flushPending()) return error_;
  if (::close(fd_) != 0) {
    fd_ = -1;
    error_ = osError("close", part_path_, errno);
    return error_;
  }
  fd_ = -1;
  if (std::rename(part_path_.c_str(), path_.c_str()) != 0) {
    error_ = osError("rename onto", path_, errno) + "; the recording is complete in " + part_path_;
    return error_;
  }
  fsyncFolderOf(path_);
  return error_;
}

}  // namespace cardemo
