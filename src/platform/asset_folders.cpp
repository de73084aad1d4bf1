#include "platform/asset_folders.hpp"

#include <cstdlib>
#include <system_error>

namespace cardemo {

namespace fs = std::filesystem;

std::vector<fs::path> assetFolders() {
  std::vector<fs::path> folders;
  if (const char* env = std::getenv("CARDEMO_ASSETS"); env != nullptr && *env != '\0') {
    folders.emplace_back(env);
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path dir = exe.parent_path();
    folders.push_back(dir / "../assets");
    folders.push_back(dir / "../../assets");
    folders.push_back(dir / "../share/cardemo/assets");
  }
  return folders;
}

}  // namespace cardemo
