#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace cardemo {
namespace {

// Writes everything, retrying short writes and interrupted calls; false with errno set on failure.
bool writeAll(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::string failure(const std::string& what, const std::string& path) {
  return "cannot " + what + " " + path + ": " + std::strerror(errno);
}

}  // namespace

std::string writeFileAtomically(const std::string& path, std::string_view contents) {
  if (path == "-") {
    std::fflush(stdout);
    if (!writeAll(STDOUT_FILENO, contents)) return failure("write", "standard output");
    return {};
  }
  // Same folder as the target, so rename() stays on one file system and is atomic.
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return failure("create", tmp);
  if (!writeAll(fd, contents) || ::fsync(fd) != 0) {
    const std::string why = failure("write", tmp);
    ::close(fd);
    ::unlink(tmp.c_str());
    return why;
  }
  if (::close(fd) != 0) {
    const std::string why = failure("write", tmp);
    ::unlink(tmp.c_str());
    return why;
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = failure("rename " + tmp + " to", path);
    ::unlink(tmp.c_str());
    return why;
  }
  // Make the rename itself durable; best effort, the file is already complete.
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return {};
}

}  // namespace cardemo
