#pragma once
/// Runs the cardemo executable from a test and captures what it prints.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace cardemo::test {

/// Exit status and output of one run.
struct CliResult {
  int status = -1;  ///< Exit status (-1 when killed by a signal).
  std::string out;  ///< Standard output.
  std::string err;  ///< Standard error.
};

/// A whole file's bytes ("" when missing).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/// A scratch folder for the running test, unique per process and per test: CTest runs the tests of
/// one binary in parallel processes.
inline std::filesystem::path scratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info != nullptr
                               ? std::string(info->test_suite_name()) + "." + info->name()
                               : std::string("global");
  const auto dir = std::filesystem::temp_directory_path() /
                   ("cardemo_test." + std::to_string(::getpid())) / test;
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to a file named `name` in the scratch folder and returns its path.
inline std::filesystem::path writeScratch(const std::string& name, const std::string& text) {
  const auto path = scratchDir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// A path under the repository's assets/ folder.
inline std::string assetPath(const std::string& relative) {
  return std::string(CARDEMO_SOURCE_DIR) + "/assets/" + relative;
}

/// Runs `cardemo ARGS` through the shell with `stdin_text` on standard input; `env` goes before the
/// command (e.g. "env -u DISPLAY" to run it with no display).
inline CliResult runCardemo(const std::string& args, const std::string& stdin_text = "",
                            const std::string& env = "") {
  const auto dir = scratchDir();
  const auto in = dir / "stdin", out = dir / "stdout", err = dir / "stderr";
  std::ofstream(in, std::ios::binary) << stdin_text;
  const std::string command = env + " '" + std::string(CARDEMO_BINARY) + "' " + args + " <" +
                              in.string() + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

}  // namespace cardemo::test
