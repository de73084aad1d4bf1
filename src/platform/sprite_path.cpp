#include "platform/sprite_path.hpp"

#include <cstdlib>
#include <fstream>

#include "platform/asset_folders.hpp"

namespace cardemo {
namespace {

bool holdsSprites(const std::string& dir) {
  return std::ifstream(dir + "/car.png", std::ios::binary).good();
}

}  // namespace

std::optional<std::string> findSpriteDir(std::string* why) {
  if (const char* env = std::getenv("CARDEMO_SPRITES"); env != nullptr && *env != '\0') {
    if (holdsSprites(env)) return std::string(env);
    if (why) *why = std::string("CARDEMO_SPRITES=") + env + " holds no car.png";
    return std::nullopt;
  }
  for (const std::filesystem::path& folder : assetFolders()) {
    const std::string dir = (folder / "sprites").lexically_normal().string();
    if (holdsSprites(dir)) return dir;
  }
  for (const char* dir : {"assets/sprites", CARDEMO_SPRITE_DIR}) {
    if (holdsSprites(dir)) return std::string(dir);
  }
  if (why) {
    *why = std::string("no sprites found in assets/sprites or ") + CARDEMO_SPRITE_DIR +
           " (run scripts/make_sprites.py or set CARDEMO_SPRITES)";
  }
  return std::nullopt;
}

}  // namespace cardemo
