#include "platform/font_path.hpp"

#include <array>
#include <cstdlib>
#include <fstream>

namespace cardemo {
namespace {

bool readable(const std::string& path) {
  return std::ifstream(path, std::ios::binary).good();
}

}  // namespace

std::optional<std::string> findFontPath(std::string* why) {
  if (const char* env = std::getenv("CARDEMO_FONT"); env != nullptr && *env != '\0') {
    if (readable(env)) return std::string(env);
    if (why) *why = std::string("CARDEMO_FONT=") + env + " is not a readable font file";
    return std::nullopt;
  }
  static constexpr std::array<const char*, 6> kCandidates{
      "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
      "/usr/share/fonts/TTF/DejaVuSans.ttf",
      "/usr/share/fonts/dejavu/DejaVuSans.ttf",
      "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
      "/usr/local/share/fonts/DejaVuSans.ttf",
      "/opt/homebrew/share/fonts/DejaVuSans.ttf",
  };
  for (const char* path : kCandidates) {
    if (readable(path)) return std::string(path);
  }
  if (why) {
    *why =
        "no DejaVu font found (looked in /usr/share/fonts): install fonts-dejavu-core or set "
        "CARDEMO_FONT=/path/to/DejaVuSans.ttf";
  }
  return std::nullopt;
}

}  // namespace cardemo
