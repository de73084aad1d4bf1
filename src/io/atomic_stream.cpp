#include "io/atomic_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace cardemo {
namespace {

std::string failure(const std::string& what, const std::string& path) {
  return "cannot " + what + " " + path + ": " + std::strerror(errno);
}

// Makes a rename durable; best effort, the file itself is already complete and synced.
void syncFolderOf(const std::string& path) {
  // Built without assigning a literal: GCC 12 at -O3 warns falsely (-Wrestrict, GCC bug 105651).
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  const std::string dir = folder.empty() ? std::string(1, '.') : folder.string();
  if (const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

AtomicStream::AtomicStream(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    file_ = stdout;
    return;
  }
  // Same folder as the target, so rename() stays on one file system and is atomic.
  temp_path_ = path_ + ".tmp." + std::to_string(::getpid());
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (file_ == nullptr) error_ = failure("create", temp_path_);
}

AtomicStream::~AtomicStream() {
  if (file_ != nullptr && !to_stdout_) {
    std::fclose(file_);
    std::remove(temp_path_.c_str());
  }
}

void AtomicStream::write(std::string_view bytes) {
  if (file_ == nullptr || !error_.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    error_ = failure("write", to_stdout_ ? std::string("standard output") : temp_path_);
  }
}

void AtomicStream::sync() {
  if (file_ == nullptr) return;
  std::fflush(file_);
  if (!to_stdout_) ::fsync(::fileno(file_));
}

std::string AtomicStream::commit() {
  if (!error_.empty()) return error_;
  if (file_ == nullptr) return path_ + ": already committed";
  if (to_stdout_) {
    file_ = nullptr;
    if (std::fflush(stdout) != 0) return failure("write", "standard output");
    return {};
  }
  const bool flushed = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    std::string why = failure("write", temp_path_);
    std::remove(temp_path_.c_str());
    return why;
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    std::string why = failure("rename " + temp_path_ + " to", path_);
    std::remove(temp_path_.c_str());
    return why;
  }
  syncFolderOf(path_);
  return {};
}

}  // namespace cardemo
