#pragma once
/// The system calls behind DurableFile, in one table that a test may swap to fail or log them.

#include <sys/types.h>

#include <cstddef>

namespace cardemo {

/// One entry per system call DurableFile makes; each has the signature and errno convention of
/// the call it is named after (open always takes the mode).
struct FileCalls {
  int (*open)(const char* path, int flags, mode_t mode);         ///< open(2)
  ssize_t (*write)(int fd, const void* data, std::size_t size);  ///< write(2)
  int (*fsync)(int fd);                                          ///< fsync(2)
  int (*ftruncate)(int fd, off_t size);                          ///< ftruncate(2)
  int (*close)(int fd);                                          ///< close(2)
  int (*rename)(const char* from, const char* to);               ///< rename(2)
  int (*unlink)(const char* path);                               ///< unlink(2)
  int (*flock)(int fd, int operation);                           ///< flock(2)
};

/// The real system calls.
[[nodiscard]] FileCalls systemFileCalls();

/// The table DurableFile calls through: systemFileCalls() unless a test replaced entries.
[[nodiscard]] FileCalls& fileCalls();

}  // namespace cardemo
