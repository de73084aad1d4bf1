#include "play/recorder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "io/replay_text.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

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

std::string osError(const std::string& what, const std::string& path) {
  return path + ": cannot " + what + ": " + std::strerror(errno);
}

}  // namespace

Recorder::Recorder(std::string path, const std::string& scene_path, int hz,
                   std::int64_t flush_every_frames)
    : path_(std::move(path)),
      part_path_(path_ + ".part"),
      flush_every_(flush_every_frames < 1 ? 1 : flush_every_frames) {
  file_ = std::fopen(part_path_.c_str(), "wb");
  if (file_ == nullptr) {
    error_ = osError("write", part_path_);
    return;
  }
  std::string header = "cardemo-replay 1\n";
  if (!scene_path.empty()) header += "scene " + sceneRelativeTo(path_, scene_path) + "\n";
  header += "hz " + std::to_string(hz) + "\n# frames  keys\n";
  std::fputs(header.c_str(), file_);
  std::fflush(file_);
}

Recorder::~Recorder() {
  (void)finish();
}

void Recorder::writeRun() {
  if (file_ == nullptr || run_length_ == 0) return;
  std::fprintf(file_, "%lld %s\n", static_cast<long long>(run_length_),
               keysText(run_keys_).c_str());
  run_length_ = 0;
}

void Recorder::record(const InputFrame& input) {
  if (finished_ || file_ == nullptr) return;
  if (run_length_ > 0 && !(input == run_keys_)) writeRun();
  run_keys_ = input;
  ++run_length_;
  ++frames_;
  if (++since_flush_ >= flush_every_) {
    // A run is split at flush points so the file on disk always ends at the current frame.
    writeRun();
    std::fflush(file_);
    ::fsync(::fileno(file_));
    since_flush_ = 0;
  }
}

std::string Recorder::finish(const std::string& trailer) {
  if (finished_) return error_;
  finished_ = true;
  if (file_ == nullptr) return error_;
  writeRun();
  if (!trailer.empty()) {
    std::fputs(trailer.c_str(), file_);
    if (trailer.back() != '\n') std::fputc('\n', file_);
  }
  bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  if (!ok) error_ = osError("write", part_path_);
  if (std::fclose(file_) != 0 && ok) {
    error_ = osError("close", part_path_);
    ok = false;
  }
  file_ = nullptr;
  if (ok && std::rename(part_path_.c_str(), path_.c_str()) != 0) {
    error_ = osError("rename onto", path_);
  }
  return error_;
}

}  // namespace cardemo
