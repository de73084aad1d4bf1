#pragma once
/// A file written as a stream and published atomically when finished.

#include <memory>
#include <string>
#include <string_view>

namespace cardemo {

class DurableFile;

/// Streams into `PATH.tmp.PID` (io/durable_file), then commit() syncs it, renames it onto PATH and
/// syncs the folder. Destroyed without commit(), it removes the temporary file, so readers never
/// see a half-written PATH. PATH "-" streams to standard output and commit() just flushes.
class AtomicStream {
 public:
  /// Opens the temporary file; check error() afterwards.
  explicit AtomicStream(std::string path);
  ~AtomicStream();
  AtomicStream(const AtomicStream&) = delete;
  AtomicStream& operator=(const AtomicStream&) = delete;

  /// Appends bytes (buffered).
  void write(std::string_view bytes);
  /// Writes the buffered bytes and fsyncs them (the data survives a crash of this process).
  void sync();
  /// Publishes the file; returns an empty string or what went wrong.
  [[nodiscard]] std::string commit();
  /// Empty, or why the file could not be opened or written.
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  bool drain();
  std::string path_;
  std::unique_ptr<DurableFile> file_;  // null for standard output and once committed
  std::string buffer_;
  bool to_stdout_ = false;
  bool committed_ = false;
  std::string error_;
};

}  // namespace cardemo
