#include "io/input_error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace cardemo {
namespace {

// Reads `fd` to the end, refusing more than `max_bytes`. Works for pipes and special files too,
// which report no useful size; `expected` (a regular file's size) is reserved up front, so a large
// file is not copied again each time the string grows.
Parsed<std::string> readAll(int fd, const std::string& path, std::size_t max_bytes,
                            std::size_t expected = 0) {
  std::string out;
  out.reserve(expected);
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      return InputError{path, 0, std::string("cannot read: ") + std::strerror(errno)};
    }
    if (out.size() + static_cast<std::size_t>(n) > max_bytes) {
      return InputError{path, 0,
                        "file is larger than the limit of " + std::to_string(max_bytes) + " bytes"};
    }
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

}  // namespace

Parsed<std::string> readInputFile(const std::string& path, std::size_t max_bytes) {
  if (path == "-") return readAll(STDIN_FILENO, path, max_bytes);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return InputError{path, 0, std::string("cannot open: ") + std::strerror(errno)};
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    return InputError{path, 0, std::string("cannot open: ") + std::strerror(err)};
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    return InputError{path, 0, std::string("cannot open: ") + std::strerror(EISDIR)};
  }
  if (S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > max_bytes) {
    ::close(fd);
    return InputError{path, 0,
                      "file is larger than the limit of " + std::to_string(max_bytes) + " bytes"};
  }
  const std::size_t expected = S_ISREG(st.st_mode) ? static_cast<std::size_t>(st.st_size) : 0;
  Parsed<std::string> result = readAll(fd, path, max_bytes, expected);
  ::close(fd);
  return result;
}

}  // namespace cardemo
