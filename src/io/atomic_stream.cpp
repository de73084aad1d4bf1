#include "io/atomic_stream.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cardemo {

AtomicStream::AtomicStream(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    file_ = stdout;
    return;
  }
  temp_path_ = path_ + ".tmp." + std::to_string(::getpid());
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (file_ == nullptr) error_ = path_ + ": cannot write: " + std::strerror(errno);
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
    error_ = path_ + ": write failed: " + std::strerror(errno);
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
    std::fflush(file_);
    file_ = nullptr;
    return {};
  }
  sync();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed || std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    std::string why = path_ + ": cannot publish: " + std::strerror(errno);
    std::remove(temp_path_.c_str());
    return why;
  }
  return {};
}

}  // namespace cardemo
