#include "platform/font_path.hpp"

#include <filesystem>
#include <system_error>

#include "io/asset_lookup.hpp"

namespace cardemo {
namespace {

// Debian's fonts-dejavu-core, for an executable run away from its assets folder.
constexpr const char* kSystemFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

std::optional<std::string> findFontPath(std::string* why) {
  std::string missing;
  if (auto font = findAsset("fonts/DejaVuSans.ttf", &missing)) return font;
  std::error_code ec;
  if (std::filesystem::exists(kSystemFont, ec)) return std::string(kSystemFont);
  if (why != nullptr) *why = missing + " or install fonts-dejavu-core";
  return std::nullopt;
}

}  // namespace cardemo
