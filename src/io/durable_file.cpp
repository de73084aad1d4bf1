#include "io/durable_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include "io/file_calls.hpp"

namespace cardemo {
namespace {

int openFile(const char* path, int flags, mode_t mode) {
  return ::open(path, flags, mode);
}

std::string reason(int err) {
  return std::strerror(err);
}

}  // namespace

FileCalls systemFileCalls() {
  return {openFile, ::write, ::fsync, ::ftruncate, ::close, ::rename, ::unlink, ::flock};
}

FileCalls& fileCalls() {
  static FileCalls calls = systemFileCalls();
  return calls;
}

std::string syncFolderOf(const std::string& path) {
  // Built without assigning a literal: GCC 12 at -O3 warns falsely (-Wrestrict, GCC bug 105651).
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? std::string(1, '.') : parent.string();
  const FileCalls& sys = fileCalls();
  const int fd = sys.open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC, 0);
  if (fd < 0) return folder + ": cannot open the folder to sync it: " + reason(errno);
  std::string why;
  // EINVAL: this file system cannot sync a folder (its renames are durable some other way).
  if (sys.fsync(fd) != 0 && errno != EINVAL) why = folder + ": cannot sync: " + reason(errno);
  (void)sys.close(fd);
  return why;
}

bool lockedByAnotherProcess(const std::string& path) {
  const FileCalls& sys = fileCalls();
  const int fd = sys.open(path.c_str(), O_RDONLY | O_CLOEXEC, 0);
  if (fd < 0) return false;
  const bool locked = sys.flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  (void)sys.close(fd);
  return locked;
}

DurableFile::DurableFile(std::string path, Existing existing) : path_(std::move(path)) {
  const int flags =
      O_WRONLY | O_CREAT | O_CLOEXEC | (existing == Existing::kRefuse ? O_EXCL : O_TRUNC);
  fd_ = fileCalls().open(path_.c_str(), flags, 0644);
  if (fd_ < 0) (void)fail("create");
  created_ = fd_ >= 0;
}

DurableFile::~DurableFile() {
  closeQuietly();
}

bool DurableFile::fail(const std::string& what) {
  errno_ = errno;
  error_ = path_ + ": cannot " + what + ": " + reason(errno_);
  return false;
}

void DurableFile::closeQuietly() {
  if (fd_ >= 0) (void)fileCalls().close(fd_);
  fd_ = -1;
}

bool DurableFile::tryLock() {
  return fd_ >= 0 && fileCalls().flock(fd_, LOCK_EX | LOCK_NB) == 0;
}

bool DurableFile::append(std::string_view bytes) {
  if (fd_ < 0) return false;
  const FileCalls& sys = fileCalls();
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = sys.write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return fail("write");
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

bool DurableFile::sync() {
  if (fd_ < 0) return false;
  return fileCalls().fsync(fd_) == 0 || fail("write");
}

bool DurableFile::truncate(std::int64_t size) {
  if (fd_ < 0) return false;
  if (fileCalls().ftruncate(fd_, static_cast<off_t>(size)) != 0) return fail("truncate");
  return sync();
}

bool DurableFile::close() {
  if (fd_ < 0) return false;
  const int fd = std::exchange(fd_, -1);
  return fileCalls().close(fd) == 0 || fail("close");
}

bool DurableFile::publishAs(const std::string& target) {
  if (!sync()) {
    closeQuietly();
    return false;
  }
  if (!close()) return false;
  if (fileCalls().rename(path_.c_str(), target.c_str()) != 0) {
    errno_ = errno;
    error_ = target + ": cannot rename " + path_ + " onto it: " + reason(errno_);
    return false;
  }
  created_ = false;  // the file is `target` now: never discarded
  published_ = true;
  if (std::string why = syncFolderOf(target); !why.empty()) {
    errno_ = EIO;
    error_ = target + ": written, but not durably: " + why;
    return false;
  }
  return true;
}

void DurableFile::discard() {
  closeQuietly();
  if (created_) (void)fileCalls().unlink(path_.c_str());
  created_ = false;
}

}  // namespace cardemo
