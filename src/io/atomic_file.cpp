#include "io/atomic_file.hpp"

#include "io/atomic_stream.hpp"

namespace cardemo {

std::string writeFileAtomically(const std::string& path, std::string_view contents) {
  AtomicStream out(path);
  out.write(contents);
  return out.commit();
}

}  // namespace cardemo
