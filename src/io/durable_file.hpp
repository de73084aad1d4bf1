#pragma once
/// Durable file output: every write, fsync, rename and folder fsync of the program happens here.

#include <cstdint>
#include <string>
#include <string_view>

namespace cardemo {

/// A file being written with write(2) and made durable with fsync(2). publishAs() syncs it,
/// renames it over its target and fsyncs the target's folder, so that the rename itself survives
/// a crash. Errors are one line, `PATH: cannot WHAT: REASON`. Destroyed, it closes the file and
/// keeps it: the owner decides between publishAs() and discard().
class DurableFile {
 public:
  /// What opening does when `path` already exists.
  enum class Existing {
    kTruncate,  ///< Start it afresh.
    kRefuse,    ///< Fail with EEXIST (O_EXCL): never overwrite it.
  };

  /// Creates `path` (mode 0644) for writing; check isOpen() or error().
  DurableFile(std::string path, Existing existing);
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  /// True until the file is published, discarded or closed, or an operation on it failed.
  [[nodiscard]] bool isOpen() const { return fd_ >= 0; }
  /// The file being written.
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Empty, or the last failure as `PATH: cannot WHAT: REASON`.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// errno of the last failure (0 when none), e.g. EEXIST for Existing::kRefuse.
  [[nodiscard]] int errorNumber() const { return errno_; }
  /// True once publishAs() renamed the file onto its target (even if the folder sync then failed).
  [[nodiscard]] bool published() const { return published_; }

  /// Takes an exclusive advisory lock (flock) without waiting; false when another process holds
  /// one. Other processes see it with lockedByAnotherProcess().
  bool tryLock();
  /// Writes all of `bytes` (short writes and EINTR are retried); false (and error()) on failure.
  bool append(std::string_view bytes);
  /// fsync: what was appended survives a crash of the process or the machine.
  bool sync();
  /// Cuts the file back to `size` bytes and syncs it (e.g. to a last known-good state).
  bool truncate(std::int64_t size);
  /// Closes the file and keeps it under its own name.
  bool close();
  /// Syncs and closes the file, renames it onto `target` (atomically replacing it), then fsyncs
  /// the folder holding `target`. A failure before the rename leaves the file closed under its
  /// own name (published() is false) and `target` untouched.
  bool publishAs(const std::string& target);
  /// Closes the file and removes it unless it was published (a temporary nobody may see).
  void discard();

 private:
  bool fail(const std::string& what);
  void closeQuietly();
  std::string path_;
  int fd_ = -1;
  std::string error_;
  int errno_ = 0;
  bool created_ = false;    // this object created path_ and has not renamed or removed it
  bool published_ = false;  // renamed onto the target
};

/// fsyncs the folder holding `path`, so that a rename or a new file in it survives a crash.
/// Empty on success (or where the file system cannot sync folders), else `FOLDER: cannot ...`.
[[nodiscard]] std::string syncFolderOf(const std::string& path);

/// True when another process holds the lock that DurableFile::tryLock takes on `path`.
[[nodiscard]] bool lockedByAnotherProcess(const std::string& path);

}  // namespace cardemo
