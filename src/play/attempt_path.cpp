#include "play/attempt_path.hpp"

namespace cardemo {

std::string attemptPath(const std::string& base, int attempt) {
  if (attempt <= 1) return base;
  const std::size_t slash = base.rfind('/');
  const std::size_t name = slash == std::string::npos ? 0 : slash + 1;
  std::size_t dot = base.rfind('.');
  // No extension: no dot in the file name, or only a leading one (a hidden file's name).
  if (dot == std::string::npos || dot <= name) dot = base.size();
  return base.substr(0, dot) + "-" + std::to_string(attempt) + base.substr(dot);
}

}  // namespace cardemo
