#include "io/printable.hpp"

namespace cardemo {

std::string printable(std::string_view bytes, std::size_t max_bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i == max_bytes) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(bytes[i]);
    if (u >= 0x20 && u < 0x7f) {
      out += bytes[i];
    } else {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    }
  }
  return out;
}

std::string inQuotes(std::string_view bytes, std::size_t max_bytes) {
  return '"' + printable(bytes, max_bytes) + '"';
}

}  // namespace cardemo
