#include "io/atomic_stream.hpp"

#include <unistd.h>

#include <cstdio>

#include "io/durable_file.hpp"

namespace cardemo {
namespace {

// Bytes gathered before one write(2).
constexpr std::size_t kBufferBytes = std::size_t{1} << 16;

}  // namespace

AtomicStream::AtomicStream(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    return;
  }
  // Same folder as the target, so the rename stays on one file system and is atomic.
  file_ = std::make_unique<DurableFile>(path_ + ".tmp." + std::to_string(::getpid()),
                                        DurableFile::Existing::kTruncate);
  if (!file_->isOpen()) error_ = file_->error();
}

AtomicStream::~AtomicStream() {
  if (file_) file_->discard();
}

bool AtomicStream::drain() {
  if (!error_.empty() || !file_) return false;
  const bool ok = file_->append(buffer_);
  buffer_.clear();
  if (!ok) error_ = file_->error();
  return ok;
}

void AtomicStream::write(std::string_view bytes) {
  if (committed_ || !error_.empty()) return;
  if (to_stdout_) {
    // Standard output goes through stdio, in order with what the program printed before.
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size()) {
      error_ = "standard output: cannot write";
    }
    return;
  }
  buffer_ += bytes;
  if (buffer_.size() >= kBufferBytes) (void)drain();
}

void AtomicStream::sync() {
  if (to_stdout_) {
    (void)std::fflush(stdout);
    return;
  }
  if (drain() && !file_->sync()) error_ = file_->error();
}

std::string AtomicStream::commit() {
  if (committed_) return path_ + ": already committed";
  committed_ = true;
  if (!error_.empty()) {
    if (file_) file_->discard();
    file_.reset();
    return error_;
  }
  if (to_stdout_) {
    if (std::fflush(stdout) != 0) return "standard output: cannot write";
    return {};
  }
  if (drain() && file_->publishAs(path_)) {
    file_.reset();
    return {};
  }
  error_ = file_->error();
  file_->discard();
  file_.reset();
  return error_;
}

}  // namespace cardemo
