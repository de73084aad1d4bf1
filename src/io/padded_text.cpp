#include "io/padded_text.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <new>
#include <optional>
#include <utility>

namespace cardemo {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Reads `size` bytes into `into` and then finds the end of the file; false on an error or when
// the file holds more or fewer bytes (it changed since its size was read).
bool readExactly(int fd, char* into, std::size_t size) {
  std::size_t done = 0;
  for (;;) {
    char past_end = 0;
    const ssize_t n = done < size ? ::read(fd, into + done, size - done) : ::read(fd, &past_end, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n == 0 && done == size;
    done += static_cast<std::size_t>(n);
    if (done > size) return false;
  }
}

}  // namespace

PaddedText::PaddedText(std::size_t size) : size_(size) {
  if (size == 0) return;
  // Anonymous memory is zero, padding included. A large text is aligned to a huge page and
  // marked for transparent huge pages: a fault then maps 2 MB instead of 4 kB, and on a virtual
  // machine, where every fault is costly, faults were most of the time of reading a large scene.
  const std::size_t needed = size + kPadding;
  const bool huge = needed >= kHugePage;
  mapped_bytes_ = huge ? needed + kHugePage : needed;
  void* mapping =
      ::mmap(nullptr, mapped_bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapping == MAP_FAILED) throw std::bad_alloc();
  mapping_ = mapping;
  std::uintptr_t start = reinterpret_cast<std::uintptr_t>(mapping);
  if (huge) {
    start = (start + kHugePage - 1) / kHugePage * kHugePage;
#ifdef MADV_HUGEPAGE
    // A hint: where transparent huge pages are off, the memory works the same.
    static_cast<void>(::madvise(reinterpret_cast<void*>(start), needed, MADV_HUGEPAGE));
#endif
  }
  buffer_ = reinterpret_cast<char*>(start);
}

PaddedText PaddedText::copyOf(std::string_view text) {
  PaddedText out(text.size());
  if (!text.empty()) std::memcpy(out.buffer_, text.data(), text.size());
  return out;
}

PaddedText::PaddedText(PaddedText&& other) noexcept
    : buffer_(std::exchange(other.buffer_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      mapping_(std::exchange(other.mapping_, nullptr)),
      mapped_bytes_(std::exchange(other.mapped_bytes_, 0)) {}

PaddedText& PaddedText::operator=(PaddedText&& other) noexcept {
  if (this != &other) {
    release();
    buffer_ = std::exchange(other.buffer_, nullptr);
    size_ = std::exchange(other.size_, 0);
    mapping_ = std::exchange(other.mapping_, nullptr);
    mapped_bytes_ = std::exchange(other.mapped_bytes_, 0);
  }
  return *this;
}

PaddedText::~PaddedText() {
  release();
}

void PaddedText::release() noexcept {
  if (mapping_ != nullptr) ::munmap(mapping_, mapped_bytes_);
  buffer_ = nullptr;
  size_ = 0;
  mapping_ = nullptr;
  mapped_bytes_ = 0;
}

Parsed<PaddedText> readPaddedFile(const std::string& path, std::size_t max_bytes) {
  if (path != "-") {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      std::optional<PaddedText> text;
      struct stat st {};
      if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
          static_cast<std::uint64_t>(st.st_size) <= max_bytes) {
        // Straight into the padded memory: no growing buffer, no second copy.
        PaddedText out(static_cast<std::size_t>(st.st_size));
        if (readExactly(fd, out.buffer_, out.size_)) text = std::move(out);
      }
      ::close(fd);
      if (text) return std::move(*text);
    }
  }
  // Standard input, pipes, special files, files that changed while read, and every error: read as
  // readInputFile reads them, so the errors are its own.
  Parsed<std::string> text = readInputFile(path, max_bytes);
  if (!text.ok()) return text.error();
  return PaddedText::copyOf(text.value());
}

}  // namespace cardemo
