#pragma once
/// A file written as a stream and published atomically when finished.

#include <cstdio>
#include <string>
#include <string_view>

namespace cardemo {

/// Streams into `PATH.tmp.PID`, then commit() flushes, fsyncs and renames it onto PATH. Destroyed
/// without commit(), it removes the temporary file, so readers never see a half-written PATH.
/// PATH "-" streams to standard output and commit() just flushes.
class AtomicStream {
 public:
  /// Opens the temporary file; check error() afterwards.
  explicit AtomicStream(std::string path);
  ~AtomicStream();
  AtomicStream(const AtomicStream&) = delete;
  AtomicStream& operator=(const AtomicStream&) = delete;

  /// Appends bytes (buffered).
  void write(std::string_view bytes);
  /// Flushes buffered bytes to the OS and fsyncs (the data survives a crash of this process).
  void sync();
  /// Publishes the file; returns an empty string or what went wrong.
  [[nodiscard]] std::string commit();
  /// Empty, or why the file could not be opened or written.
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool to_stdout_ = false;
  std::string error_;
};

}  // namespace cardemo
