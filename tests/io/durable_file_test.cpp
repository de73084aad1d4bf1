// The durable-write module: the target is replaced atomically (by rename, never rewritten in
// place), a failure at any step leaves the old file and no temporary, and the folder is synced
// after the rename. Failures are injected, and the order of the system calls logged, through the
// FileCalls table.

#include "io/durable_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "../support/cli_run.hpp"
#include "../support/temp_dir.hpp"
#include "io/atomic_file.hpp"
#include "io/atomic_stream.hpp"
#include "io/file_calls.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

ino_t inodeOf(const fs::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

// Every call DurableFile makes, as "call PATH" with the path its descriptor was opened on, and
// which call (by name) fails with which errno; the real call runs otherwise.
struct CallLog {
  std::vector<std::string> calls;
  std::map<int, std::string> open_paths;
  std::map<int, bool> is_folder;
  std::string failing;       // name of the call that fails
  bool fail_folder = false;  // with "fsync": fail only on a folder's descriptor
  int failing_errno = EIO;
};

CallLog& callLog() {
  static CallLog log;
  return log;
}

bool shouldFail(const std::string& call, int fd = -1) {
  CallLog& log = callLog();
  if (log.failing != call) return false;
  if (call == "fsync" && log.fail_folder != log.is_folder[fd]) return false;
  errno = log.failing_errno;
  return true;
}

std::string pathOf(int fd) {
  return callLog().open_paths[fd];
}

// Installs the logging table for one test and puts the real one back afterwards.
class LoggedCalls {
 public:
  LoggedCalls() {
    callLog() = {};
    FileCalls& c = fileCalls();
    c.open = [](const char* path, int flags, mode_t mode) {
      if (shouldFail("open")) return -1;
      const int fd = systemFileCalls().open(path, flags, mode);
      callLog().calls.push_back(std::string("open ") + path);
      callLog().open_paths[fd] = path;
      callLog().is_folder[fd] = (flags & O_DIRECTORY) != 0;
      return fd;
    };
    c.write = [](int fd, const void* data, std::size_t n) -> ssize_t {
      if (shouldFail("write")) return -1;
      callLog().calls.push_back("write " + pathOf(fd));
      return systemFileCalls().write(fd, data, n);
    };
    c.fsync = [](int fd) {
      if (shouldFail("fsync", fd)) return -1;
      callLog().calls.push_back("fsync " + pathOf(fd));
      return systemFileCalls().fsync(fd);
    };
    c.close = [](int fd) {
      callLog().calls.push_back("close " + pathOf(fd));
      return systemFileCalls().close(fd);
    };
    c.rename = [](const char* from, const char* to) {
      if (shouldFail("rename")) return -1;
      callLog().calls.push_back(std::string("rename ") + from + " " + to);
      return systemFileCalls().rename(from, to);
    };
    c.unlink = [](const char* path) {
      callLog().calls.push_back(std::string("unlink ") + path);
      return systemFileCalls().unlink(path);
    };
  }
  ~LoggedCalls() { fileCalls() = systemFileCalls(); }
  LoggedCalls(const LoggedCalls&) = delete;
  LoggedCalls& operator=(const LoggedCalls&) = delete;
};

std::ptrdiff_t indexOf(const std::vector<std::string>& calls, const std::string& call) {
  const auto it = std::find(calls.begin(), calls.end(), call);
  return it == calls.end() ? -1 : it - calls.begin();
}

class DurableFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::freshTempDir(std::string("durable_") +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    target_ = dir_ / "out.txt";
    std::ofstream(target_, std::ios::binary) << "old contents";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  fs::path target_;
};

TEST_F(DurableFiles, PublishReplacesTheTargetByRenameAndSyncsTheFolderAfterIt) {
  const LoggedCalls logged;
  const fs::path temp = dir_ / "out.txt.tmp";
  DurableFile file(temp.string(), DurableFile::Existing::kTruncate);
  ASSERT_TRUE(file.isOpen()) << file.error();
  ASSERT_TRUE(file.append("new contents"));
  ASSERT_TRUE(file.sync());
  EXPECT_EQ(test::slurp(target_), "old contents") << "readers see the old file until the rename";
  const ino_t written = inodeOf(temp);
  ASSERT_TRUE(file.publishAs(target_.string())) << file.error();
  EXPECT_TRUE(file.published());
  EXPECT_EQ(test::slurp(target_), "new contents");
  EXPECT_EQ(inodeOf(target_), written) << "the written file itself, renamed, not a copy";
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.txt"});

  const std::vector<std::string>& calls = callLog().calls;
  const auto sync_file = indexOf(calls, "fsync " + temp.string());
  const auto rename = indexOf(calls, "rename " + temp.string() + " " + target_.string());
  const auto sync_folder = indexOf(calls, "fsync " + dir_.string());
  ASSERT_GE(sync_file, 0);
  ASSERT_GE(rename, 0);
  ASSERT_GE(sync_folder, 0) << "the folder holding the target must be synced";
  EXPECT_LT(sync_file, rename);
  EXPECT_LT(rename, sync_folder) << "the folder is synced after the rename, so it survives";
}

TEST_F(DurableFiles, WriteFileAtomicallyRunsTheSameSequence) {
  const LoggedCalls logged;
  ASSERT_EQ(writeFileAtomically(target_.string(), "new"), "");
  EXPECT_EQ(test::slurp(target_), "new");
  const std::vector<std::string>& calls = callLog().calls;
  ASSERT_GE(calls.size(), 6u);
  // open temp, write temp, fsync temp, close temp, rename, open folder, fsync folder, close.
  EXPECT_EQ(calls[0].rfind("open " + target_.string() + ".tmp.", 0), 0u) << calls[0];
  const std::string temp = calls[0].substr(5);
  EXPECT_EQ(calls[1], "write " + temp);
  EXPECT_EQ(calls[2], "fsync " + temp);
  EXPECT_EQ(calls[3], "close " + temp);
  EXPECT_EQ(calls[4], "rename " + temp + " " + target_.string());
  EXPECT_EQ(calls[5], "open " + dir_.string());
  EXPECT_EQ(calls[6], "fsync " + dir_.string());
}

// A failure at each step before the rename: the old file stays, the temporary is removed, and
// the message names the file and the reason on one line.
TEST_F(DurableFiles, AFailedStepLeavesTheOldFileAndNoTemporary) {
  for (const char* step : {"write", "fsync", "rename"}) {
    SCOPED_TRACE(step);
    const LoggedCalls logged;
    callLog().failing = step;
    callLog().failing_errno = ENOSPC;
    const std::string why = writeFileAtomically(target_.string(), "new contents");
    EXPECT_NE(why, "");
    EXPECT_NE(why.find("No space left on device"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    EXPECT_EQ(why.rfind(target_.string(), 0), 0u) << "PATH: what went wrong: " << why;
    EXPECT_EQ(test::slurp(target_), "old contents");
    EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.txt"}) << "temporary left behind";
  }
}

TEST_F(DurableFiles, AStreamThatFailsMidWayLeavesTheOldFile) {
  const LoggedCalls logged;
  AtomicStream out(target_.string());
  ASSERT_EQ(out.error(), "");
  out.write(std::string(100'000, 'x'));  // more than the buffer: one write(2) already happened
  callLog().failing = "write";
  out.write(std::string(100'000, 'y'));
  EXPECT_NE(out.error(), "");
  EXPECT_NE(out.commit(), "");
  EXPECT_EQ(test::slurp(target_), "old contents");
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.txt"});
}

TEST_F(DurableFiles, AFailedFolderSyncIsReportedAfterTheFileIsInPlace) {
  const LoggedCalls logged;
  callLog().failing = "fsync";
  callLog().fail_folder = true;
  const std::string why = writeFileAtomically(target_.string(), "new");
  EXPECT_NE(why.find("not durably"), std::string::npos) << why;
  EXPECT_NE(why.find("Input/output error"), std::string::npos) << why;
  EXPECT_EQ(test::slurp(target_), "new") << "the rename happened; only its durability is in doubt";
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.txt"});
}

TEST_F(DurableFiles, AFolderThatCannotBeSyncedIsNotAnError) {
  const LoggedCalls logged;
  callLog().failing = "fsync";
  callLog().fail_folder = true;
  callLog().failing_errno = EINVAL;  // what file systems that cannot sync folders answer
  EXPECT_EQ(writeFileAtomically(target_.string(), "new"), "");
  EXPECT_EQ(test::slurp(target_), "new");
}

TEST_F(DurableFiles, RefusingAnExistingFileLeavesItAlone) {
  DurableFile file(target_.string(), DurableFile::Existing::kRefuse);
  EXPECT_FALSE(file.isOpen());
  EXPECT_EQ(file.errorNumber(), EEXIST);
  EXPECT_EQ(file.error().rfind(target_.string() + ": cannot create: ", 0), 0u) << file.error();
  file.discard();  // not ours: never removed
  EXPECT_EQ(test::slurp(target_), "old contents");
}

TEST_F(DurableFiles, TruncateGoesBackToAKnownLength) {
  const fs::path part = dir_ / "log.part";
  DurableFile file(part.string(), DurableFile::Existing::kRefuse);
  ASSERT_TRUE(file.append("kept\n"));
  ASSERT_TRUE(file.sync());
  ASSERT_TRUE(file.append("torn li"));
  ASSERT_TRUE(file.truncate(5));
  ASSERT_TRUE(file.close());
  EXPECT_EQ(test::slurp(part), "kept\n");
}

TEST_F(DurableFiles, DiscardRemovesTheFileButNeverAPublishedOne) {
  const fs::path temp = dir_ / "t.tmp";
  {
    DurableFile file(temp.string(), DurableFile::Existing::kTruncate);
    ASSERT_TRUE(file.append("x"));
    file.discard();
  }
  EXPECT_FALSE(fs::exists(temp));
  DurableFile file(temp.string(), DurableFile::Existing::kTruncate);
  ASSERT_TRUE(file.append("y"));
  ASSERT_TRUE(file.publishAs(target_.string()));
  file.discard();
  EXPECT_EQ(test::slurp(target_), "y");
}

TEST_F(DurableFiles, ALockIsSeenByOtherOpeners) {
  const fs::path part = dir_ / "lock.part";
  DurableFile file(part.string(), DurableFile::Existing::kRefuse);
  EXPECT_FALSE(lockedByAnotherProcess(part.string()));
  ASSERT_TRUE(file.tryLock());
  // flock locks belong to the open file description: a second open in this process conflicts
  // exactly as another process's would.
  EXPECT_TRUE(lockedByAnotherProcess(part.string()));
  ASSERT_TRUE(file.close());
  EXPECT_FALSE(lockedByAnotherProcess(part.string()));
}

TEST_F(DurableFiles, SyncFolderOfAPlainNameSyncsTheWorkingFolder) {
  const LoggedCalls logged;
  EXPECT_EQ(syncFolderOf("relative-name.txt"), "");
  EXPECT_EQ(callLog().calls.front(), "open .");
  EXPECT_EQ(syncFolderOf((dir_ / "no/such/x").string()).find(": cannot open the folder"),
            (dir_ / "no/such").string().size());
}

}  // namespace
}  // namespace cardemo
