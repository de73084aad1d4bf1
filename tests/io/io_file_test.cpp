#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/atomic_file.hpp"
#include "io/atomic_stream.hpp"
#include "io/input_error.hpp"
#include "io/replay_text.hpp"
#include "io/scene_json.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class IoFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cardemo_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& contents) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << contents;
    return p.string();
  }

  static std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  fs::path dir_;
};

TEST_F(IoFiles, ReadsAWholeFile) {
  const std::string path = write("a.txt", std::string("x\0y\n", 4));
  const Parsed<std::string> p = readInputFile(path, 100);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.value(), std::string("x\0y\n", 4));
}

TEST_F(IoFiles, MissingFileIsAnErrorWithoutLine) {
  const Parsed<std::string> p = readInputFile((dir_ / "nope.json").string(), 100);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().line, 0);
  EXPECT_EQ(p.error().toString(),
            (dir_ / "nope.json").string() + ": cannot open: No such file or directory");
}

TEST_F(IoFiles, DirectoryIsAnError) {
  const Parsed<std::string> p = readInputFile(dir_.string(), 100);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().line, 0);
  EXPECT_NE(p.error().message.find("cannot open: Is a directory"), std::string::npos);
}

TEST_F(IoFiles, FileOverTheLimitIsRefused) {
  const std::string path = write("big.txt", std::string(101, 'a'));
  const Parsed<std::string> p = readInputFile(path, 100);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("larger than the limit of 100 bytes"), std::string::npos);
  EXPECT_TRUE(readInputFile(write("ok.txt", std::string(100, 'a')), 100).ok());
}

TEST_F(IoFiles, SpecialFileOverTheLimitIsRefused) {
  const Parsed<std::string> p = readInputFile("/dev/zero", 1000);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("larger than"), std::string::npos);
}

TEST_F(IoFiles, LoadSceneAndReplayFromDisk) {
  write("lot.json", R"({"format": "cardemo-scene/1",
      "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8}, "parked": []})");
  const std::string replay = write("r.txt", "cardemo-replay 1\nscene lot.json\n10 U\n");
  const Parsed<Replay> r = loadReplay(replay);
  ASSERT_TRUE(r.ok()) << r.error().toString();
  EXPECT_EQ(r.value().scene_resolved, (dir_ / "lot.json").string());
  const Parsed<Scene> s = loadScene(r.value().scene_resolved);
  ASSERT_TRUE(s.ok()) << s.error().toString();
  EXPECT_EQ(s.value().name, "lot");
}

TEST_F(IoFiles, SceneErrorCarriesThePath) {
  const std::string path = write("bad.json", "{\n  \"format\": \"x\"\n}\n");
  const Parsed<Scene> s = loadScene(path);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().toString(), path + ":2: format: expected \"cardemo-scene/1\", found \"x\"");
}

TEST_F(IoFiles, AtomicWriteReplacesTheFileAndLeavesNoTemporary) {
  const std::string path = write("out.json", "old contents that are longer");
  EXPECT_EQ(writeFileAtomically(path, "new"), "");
  EXPECT_EQ(slurp(path), "new");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST_F(IoFiles, AtomicWriteCreatesANewFile) {
  const std::string path = (dir_ / "fresh.txt").string();
  EXPECT_EQ(writeFileAtomically(path, std::string("a\0b", 3)), "");
  EXPECT_EQ(slurp(path), std::string("a\0b", 3));
}

TEST_F(IoFiles, AtomicWriteIntoAMissingFolderFails) {
  const std::string why = writeFileAtomically((dir_ / "no/such/dir/x.txt").string(), "x");
  EXPECT_NE(why.find("cannot create"), std::string::npos) << why;
  EXPECT_NE(why.find("No such file or directory"), std::string::npos) << why;
}

TEST_F(IoFiles, AtomicStreamPublishesOnlyOnCommit) {
  const std::string path = write("trace.csv", "previous run");
  {
    AtomicStream out(path);
    ASSERT_EQ(out.error(), "");
    out.write("frame,x\n");
    out.sync();
    EXPECT_EQ(slurp(path), "previous run");  // readers still see the old file
  }                                          // destroyed without commit: abandoned
  EXPECT_EQ(slurp(path), "previous run");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);  // no temporary left behind

  AtomicStream out(path);
  out.write("frame,x\n");
  out.write("0,1\n");
  EXPECT_EQ(out.commit(), "");
  EXPECT_EQ(slurp(path), "frame,x\n0,1\n");
  EXPECT_NE(out.commit(), "");  // a second commit is refused
}

TEST_F(IoFiles, AtomicWriteOverADirectoryFailsAndCleansUp) {
  fs::create_directories(dir_ / "target" / "child");
  const std::string why = writeFileAtomically((dir_ / "target").string(), "x");
  EXPECT_NE(why.find("cannot rename"), std::string::npos) << why;
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1);  // the temporary was removed
}

}  // namespace
}  // namespace cardemo
