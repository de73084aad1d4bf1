// No lost data: the real `cardemo play --record` is killed at seeded random moments (SIGKILL,
// SIGINT, SIGTERM, SIGHUP) while it plays back a known input stream (--replay), and what it left
// is replayed. Playback makes the recorded inputs a prefix of the known stream, and --progress
// prints every frame as it is stepped, so the frames lost can be checked against the game's
// progress: none for the signals it handles, at most a second's worth for SIGKILL.
//
// The game runs under SDL's `offscreen` video driver: the software renderer draws into memory, so
// no X server (and no xdotool: playback needs no keys) is involved, and each run starts in a
// fraction of a second. The Xvfb end-to-end test (play_e2e_test.cpp) covers the real window.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "../support/cli_run.hpp"
#include "io/replay_text.hpp"

namespace cardemo {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::slurp;

constexpr int kHz = 120;

// Starts `cardemo play ARGS` with the offscreen driver, stdout to `out`, stderr to `err`.
pid_t startGame(const std::vector<std::string>& args, const fs::path& out, const fs::path& err) {
  std::fflush(stdout);  // or the child would print this process's buffered lines again
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid == 0) {
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    if (std::freopen(out.c_str(), "w", stdout) == nullptr) _exit(126);
    if (std::freopen(err.c_str(), "w", stderr) == nullptr) _exit(126);
    std::vector<std::string> argv{CARDEMO_BINARY, "play"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> raw;
    for (std::string& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    execv(raw[0], raw.data());
    _exit(127);
  }
  return pid;
}

// Waits for the game to exit (killing it after `timeout`); returns the raw wait status.
int waitGame(pid_t pid, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(10ms);
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  ADD_FAILURE() << "the game did not exit within " << timeout.count() << " ms";
  return status;
}

// The last frame number the game printed (--progress), or -1.
std::int64_t lastProgress(const fs::path& progress) {
  const std::string text = slurp(progress);
  const std::size_t end = text.rfind('\n');
  if (end == std::string::npos) return -1;
  const std::size_t start = text.rfind('\n', end - 1);
  return std::stoll(text.substr(start == std::string::npos ? 0 : start + 1));
}

std::vector<InputFrame> framesOf(const Replay& r) {
  std::vector<InputFrame> out;
  for (const InputRun& run : r.runs) out.insert(out.end(), run.count, run.keys);
  return out;
}

// A seeded random drive of `seconds` at 120 Hz in a walled lot with no cars (no game over),
// written as a replay next to its scene.
std::vector<InputFrame> writeKnownDrive(const fs::path& dir, std::uint64_t seed, int seconds) {
  std::ofstream(dir / "lot.json")
      << R"({"format": "cardemo-scene/1", "bounds": {"min": [-50, -50], "max": [50, 50]},
            "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8},
            "parked": []})";
  std::mt19937_64 rng(seed);
  Replay replay;
  replay.scene = "lot.json";
  replay.hz = kHz;
  std::int64_t total = 0;
  while (total < static_cast<std::int64_t>(seconds) * kHz) {
    const InputRun run{std::uniform_int_distribution<std::int64_t>(1, 90)(rng),
                       InputFrame::fromBits(static_cast<std::uint8_t>(rng() % 16))};
    replay.runs.push_back(run);
    total += run.count;
  }
  std::ofstream(dir / "known.replay") << formatReplay(replay);
  return framesOf(replay);
}

TEST(RecordingKill, RandomMomentsLoseAtMostTheLastSecond) {
  const fs::path dir = test::scratchDir();
  const std::vector<InputFrame> known = writeKnownDrive(dir, 0x6b11, 60);
  std::mt19937_64 rng(0x6b12);
  const int signals[] = {SIGKILL, SIGINT, SIGTERM, SIGHUP};
  int max_lost_on_kill = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const int sig = signals[trial % 4];
    SCOPED_TRACE("trial " + std::to_string(trial) + ", signal " + std::to_string(sig));
    const fs::path record = dir / ("run" + std::to_string(trial) + ".replay");
    const fs::path progress = dir / ("progress" + std::to_string(trial) + ".txt");
    const fs::path log = dir / ("play" + std::to_string(trial) + ".log");
    const pid_t pid = startGame(
        {"--replay", (dir / "known.replay").string(), "--record", record.string(), "--progress"},
        progress, log);
    ASSERT_GT(pid, 0);
    // Kill at a random moment 0.05..2.2 s after the first frame (before and after the first
    // once-a-second flushes).
    const auto started = std::chrono::steady_clock::now();
    while (lastProgress(progress) < 1 && std::chrono::steady_clock::now() - started < 15s) {
      std::this_thread::sleep_for(5ms);
    }
    ASSERT_GE(lastProgress(progress), 1) << "the game did not start: " << slurp(log);
    std::this_thread::sleep_for(
        std::chrono::milliseconds(std::uniform_int_distribution<int>(50, 2200)(rng)));
    ASSERT_EQ(kill(pid, sig), 0);
    const int status = waitGame(pid, 10s);
    // Frames stepped: every one is printed after it is recorded; a SIGKILL may land between the
    // step and its line, so the game may have stepped one more than it printed.
    const std::int64_t printed = lastProgress(progress);

    const fs::path kept = sig == SIGKILL ? fs::path(record.string() + ".part") : record;
    if (sig == SIGKILL) {
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
      EXPECT_FALSE(fs::exists(record)) << "a killed game cannot have finished its recording";
    } else {
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status << slurp(log);
      EXPECT_FALSE(fs::exists(record.string() + ".part"));
      EXPECT_NE(slurp(log).find("stopped by signal " + std::to_string(sig)), std::string::npos)
          << slurp(log);
    }
    ASSERT_TRUE(fs::exists(kept)) << slurp(log);
    const Parsed<Replay> left = loadReplay(kept.string());
    ASSERT_TRUE(left.ok()) << left.error().toString() << "\n" << slurp(kept);
    const std::vector<InputFrame> recorded = framesOf(left.value());
    const auto frames = static_cast<std::int64_t>(recorded.size());
    ASSERT_LE(frames, static_cast<std::int64_t>(known.size()));
    EXPECT_TRUE(std::equal(recorded.begin(), recorded.end(), known.begin()))
        << "the recording is not a prefix of the inputs played";
    if (sig == SIGKILL) {
      EXPECT_LE(frames, printed + 1);
      // At most one second (hz frames) lost: a kill during the flush at frame 120 keeps none of
      // the 120 played.
      EXPECT_GE(frames, printed + 1 - kHz)
          << "more than a second lost: " << frames << " frames kept of " << printed << " played";
      max_lost_on_kill = std::max(max_lost_on_kill, static_cast<int>(printed - frames));
    } else {
      EXPECT_EQ(frames, printed) << "a handled signal must lose nothing";
    }
    // What was left replays headless, through the command line as a user would run it.
    const test::CliResult replay = test::runCardemo("replay " + kept.string());
    EXPECT_EQ(replay.status, 0) << replay.err;
    if (sig == SIGKILL && trial == 0) {
      // A later game with the same --record keeps the leftover and says where it is.
      const std::string before = slurp(kept);
      setenv("SDL_VIDEODRIVER", "offscreen", 1);
      const test::CliResult again = test::runCardemo("play --record " + record.string());
      unsetenv("SDL_VIDEODRIVER");
      EXPECT_EQ(again.status, 2);
      EXPECT_NE(again.err.find("left over"), std::string::npos) << again.err;
      EXPECT_NE(again.err.find(kept.string()), std::string::npos) << again.err;
      EXPECT_EQ(slurp(kept), before);
    }
    std::printf("[ kill ] signal %d after %lld frames played: %lld recorded\n", sig,
                static_cast<long long>(printed), static_cast<long long>(frames));
  }
  std::printf("[ kill ] most frames lost to SIGKILL: %d (limit %d)\n", max_lost_on_kill, kHz);
}

// Game over publishes the recording at once: a game killed after it leaves the complete file.
TEST(RecordingKill, GameOverPublishesBeforeAnyKill) {
  const fs::path dir = test::scratchDir();
  // 12 m/s towards a car 6 m ahead with 5 health: the first hit ends the game.
  std::ofstream(dir / "crash.json") << R"({"format": "cardemo-scene/1",
            "player": {"x": 0, "y": 0, "heading_deg": 0, "length": 4.5, "width": 1.8,
                       "health": 5, "speed": 12},
            "parked": [{"id": "wall", "x": 9, "y": 0, "heading_deg": 90, "length": 4.5,
                        "width": 1.8}]})";
  std::ofstream(dir / "coast.replay") << "cardemo-replay 1\nscene crash.json\nhz 120\n6000 .\n";
  const fs::path record = dir / "over.replay";
  const pid_t pid = startGame(
      {"--replay", (dir / "coast.replay").string(), "--record", record.string(), "--progress"},
      dir / "progress.txt", dir / "play.log");
  const auto started = std::chrono::steady_clock::now();
  while (!fs::exists(record) && std::chrono::steady_clock::now() - started < 15s) {
    std::this_thread::sleep_for(10ms);
  }
  std::this_thread::sleep_for(200ms);  // the game stays open after game over
  kill(pid, SIGKILL);
  (void)waitGame(pid, 10s);
  ASSERT_TRUE(fs::exists(record)) << slurp(dir / "play.log");
  EXPECT_FALSE(fs::exists(record.string() + ".part"));
  const test::CliResult replay = test::runCardemo("replay " + record.string() + " --json -");
  ASSERT_EQ(replay.status, 0) << replay.err;
  EXPECT_NE(replay.out.find("\"game_over\": true"), std::string::npos) << replay.out;
  EXPECT_EQ(lastProgress(dir / "progress.txt"), loadReplay(record.string()).value().totalFrames())
      << "the recording ends at the game-over frame";
}

}  // namespace
}  // namespace cardemo
