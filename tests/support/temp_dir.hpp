#pragma once
/// A fresh scratch folder per test and process.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace cardemo::testing {

/// An empty folder `cardemo_NAME_PID` under the system's temporary folder (emptied if it exists).
inline std::filesystem::path freshTempDir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("cardemo_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace cardemo::testing
