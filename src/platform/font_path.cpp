#include "platform/font_path.hpp"

#include <cstdlib>
#include <fstream>

#include "platform/asset_folders.hpp"

namespace cardemo {
namespace {

bool readable(const std::string& path) {
  return std::ifstream(path, std::ios::binary).good();
}

// Debian's fonts-dejavu-core, for an executable run away from its assets folder.
constexpr const char* kSystemFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

std::optional<std::string> findFontPath(std::string* why) {
  if (const char* env = std::getenv("CARDEMO_FONT"); env != nullptr && *env != '\0') {
    if (readable(env)) return std::string(env);
    if (why) *why = std::string("CARDEMO_FONT=") + env + " is not a readable font file";
    return std::nullopt;
  }
  for (const std::filesystem::path& folder : assetFolders()) {
    const std::filesystem::path font = folder / "fonts/DejaVuSans.ttf";
    if (readable(font.string())) return font.lexically_normal().string();
  }
  if (readable(kSystemFont)) return std::string(kSystemFont);
  if (why) {
    *why =
        "no DejaVuSans.ttf in the assets folder (assets/fonts) or in /usr/share/fonts: set "
        "CARDEMO_ASSETS to the assets folder or CARDEMO_FONT=/path/to/DejaVuSans.ttf";
  }
  return std::nullopt;
}

}  // namespace cardemo
