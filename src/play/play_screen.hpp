#pragma once
/// A level being played, with no window and no clock: every rule of the game screen (restart,
/// pause, help, the YOUR TURN hand-over, zoom, sound, the status line, the end panels, the next
/// level, the summary JSON and the recordings) in one call per drawn frame, which the SDL window
/// and the web page both make. Actions in; what to draw, play and write out.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "play/analog_drive.hpp"
#include "play/chain_run.hpp"
#include "play/fixed_step_clock.hpp"
#include "play/game_session.hpp"
#include "play/input_latch.hpp"
#include "play/level_run.hpp"
#include "play/play_flow.hpp"
#include "play/play_frame.hpp"
#include "play/sound_mix.hpp"
#include "render/camera_rig.hpp"
#include "render/effects.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo {

/// The platform's sound, as far as the rules need to know it.
struct SoundDevice {
  bool available = true;          ///< Sound plays (a device is open and the sounds are loaded).
  std::string problem;            ///< Empty, or one sentence on why the game is silent.
  bool problem_reported = false;  ///< The problem was said already (it is said once a program).
};

/// What a level starts from; the platform fills it.
struct PlayScreenConfig {
  SessionConfig session;         ///< Scene, rate, playback and recording.
  std::string json_path;         ///< Summary JSON (empty: none), see PlayScreen.
  std::string replay_path;       ///< The replay being played, for the status line (may be empty).
  std::string best_scores_path;  ///< The best-scores file (empty: scores are not kept).
  LevelLinks links;              ///< Started from the picker, and whether a next level follows.
  bool muted = false;            ///< Start with the sound off (M toggles).
  SoundDevice sound;             ///< The platform's sound.
  Eigen::Vector2i viewport{1280, 720};  ///< Drawable size at the start, pixels (fits the camera).
  /// Called with each frame's number as soon as it is simulated (`--progress`); may be empty.
  std::function<void(std::int64_t frame)> on_step;
};

/// How one level ended.
struct GameOutcome {
  int status = 0;                     ///< 0, or 2 when an output could not be written.
  LevelExit exit = LevelExit::kQuit;  ///< What the player asked for (kQuit also when stopped).
  int last_attempt = 1;               ///< Number of the last attempt played (recording paths).
};

/// One level (or free drive, with its bay chain when the scene has free bays) from start to leave.
/// Construct it, check ready(), call frame() once per drawn frame until its exit is not kStay (or
/// the platform is told to stop), then finish(). After every call, takeMessages() gives the lines
/// for standard error.
///
/// Writes: the recording of each attempt is published when the attempt ends (GAME OVER, PARKED,
/// TIME UP (a level's or the bay chain's), restart, leaving); the summary JSON is written when an
/// attempt ends and again by finish(), so the file left describes the last attempt.
class PlayScreen {
 public:
  /// Most fixed steps per frame: a slower frame drops time instead of spiralling.
  static constexpr int kMaxStepsPerFrame = 8;
  /// The + and - keys scale the camera's zoom by zoom / kDefaultZoom, within these bounds.
  static constexpr double kDefaultZoom = 12.0, kMinZoom = 2.0, kMaxZoom = 80.0;
  /// The banner shown when a replay has run out.
  static constexpr const char* kYourTurn = "YOUR TURN: drive to take over";

  /// Starts the session (and its recording) at frame 0.
  explicit PlayScreen(PlayScreenConfig config);
  PlayScreen(const PlayScreen&) = delete;
  PlayScreen& operator=(const PlayScreen&) = delete;

  /// False when the recording could not start: then the level is not played (no frame()),
  /// takeMessages() says why and outcome() has status 2.
  [[nodiscard]] bool ready() const { return ready_; }

  /// One drawn frame: applies `input.actions` in order, then runs the fixed steps that
  /// `input.elapsed_seconds` is worth (none while paused, in the help or at YOUR TURN; at most
  /// kMaxStepsPerFrame), and says what to draw, play and do. The reference stays valid until the
  /// next call.
  const PlayFrame& frame(const PlayInput& input);
  /// Shows `note` in the status line (e.g. where the platform saved a screenshot).
  void showNote(std::string note) { note_ = std::move(note); }
  /// Publishes the last attempt's recording and writes the summary JSON; the outcome.
  GameOutcome finish();
  /// The outcome so far: status, where the player asked to go, the last attempt's number.
  [[nodiscard]] GameOutcome outcome() const;

  /// Lines for standard error since the last call, oldest first.
  [[nodiscard]] std::vector<std::string> takeMessages();
  /// Paths of the recordings published since the last call (each a complete replay).
  [[nodiscard]] std::vector<std::string> takePublished();
  /// The sound's problem has been said (by this level or, per the config, an earlier one).
  [[nodiscard]] bool soundProblemReported() const { return config_.sound.problem_reported; }

  /// The session: world, attempt, recording.
  [[nodiscard]] const GameSession& session() const { return session_; }
  /// The level's challenge and best score.
  [[nodiscard]] const LevelRun& level() const { return level_; }
  /// Free drive's bay chain and best (no chain in a level or a lot without free bays).
  [[nodiscard]] const ChainRun& chain() const { return chain_; }
  /// The attempt has ended (GAME OVER, PARKED, TIME UP): nothing more is simulated until a
  /// restart.
  [[nodiscard]] bool ended() const { return session_.ended() || level_.over() || chain_.over(); }
  /// The user's zoom factor (1 at the start).
  [[nodiscard]] double userZoom() const { return zoom_ / kDefaultZoom; }

 private:
  // What the frame's actions asked for beyond what they change at once.
  struct Requests {
    bool quit = false;
    bool escape = false;
    bool next = false;
    bool confirm = false;
    bool restart = false;
    bool toggle_mute = false;
  };
  void apply(const PlayAction& action, Requests& requests);
  const PlayFrame& leave(LevelExit exit);
  void measureFps(double elapsed_seconds);
  void restart();
  void toggleMute();
  void runSteps(int steps, const PadState& pad);
  void reportAfterSteps();
  void compose(const Eigen::Vector2i& viewport);
  [[nodiscard]] nlohmann::json summary() const;
  std::string publishRecording();
  void notePublished(bool was_recording);
  void writeSummary();
  void reportRecordError();
  void say(std::string line) { messages_.push_back(std::move(line)); }

  PlayScreenConfig config_;  // its session is moved into session_
  bool keeps_best_;
  FixedStepClock clock_;
  GameSession session_;
  Effects effects_;
  CameraRig rig_;
  LevelRun level_;
  ChainRun chain_;
  InputLatch latch_;
  AnalogDrive analog_;
  PlayFlow flow_;
  SoundMix sound_;
  InputFrame last_input_;
  GoalView goal_view_;
  PlayFrame out_;
  std::string note_;
  std::vector<std::string> messages_;
  std::vector<std::string> published_;
  double zoom_ = kDefaultZoom;
  double fps_ = 0.0;
  std::int64_t drawn_frames_ = 0;
  int status_ = 0;
  LevelExit exit_ = LevelExit::kQuit;
  bool muted_ = false;
  bool over_reported_ = false;
  bool record_error_reported_ = false;
  bool ready_ = true;
};

}  // namespace cardemo
