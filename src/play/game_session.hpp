#pragma once
/// One game: the World, restart, replay playback and recording, with no window and no clock.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/obb2.hpp"
#include "io/replay_text.hpp"
#include "play/attempt_path.hpp"
#include "play/recorder.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Everything a session needs; the caller loads the files.
struct SessionConfig {
  Scene scene;                          ///< The scene to (re)start from.
  std::string scene_path;               ///< Its file, named in the recording.
  WorldSettings settings;               ///< Fixed rate and tuning.
  std::vector<InputRun> playback;       ///< Replay inputs played first (may be empty).
  std::string record_path;              ///< Where to record (empty: no recording).
  std::int64_t flush_every_frames = 0;  ///< Recording flush period; 0 means one second.
  /// Number of the first attempt (its recording path): games started one after another from the
  /// picker continue the count, so no attempt overwrites another's recording.
  int first_attempt = 1;
};

/// The game's state machine: each step() takes the replay's input while it lasts, else the live
/// input; it is the one path for live play and playback, and every simulated step is recorded.
class GameSession {
 public:
  /// Starts at frame 0 (and starts the recording, when asked).
  explicit GameSession(SessionConfig config);

  /// Simulates one fixed step unless the game is over; returns the input used.
  InputFrame step(const InputFrame& live);
  /// A fresh World from the scene; playback restarts and so does the recording: the previous
  /// attempt is published first, and this one records to attemptPath(record_path, attempt()),
  /// so no attempt overwrites another's file.
  void restart();
  /// Finishes and publishes the recording (idempotent); empty or what went wrong.
  std::string finishRecording();

  /// The world.
  [[nodiscard]] const World& world() const { return *world_; }
  /// True once this attempt has ended (GAME OVER): nothing more is simulated, and Enter or Space
  /// restarts.
  [[nodiscard]] bool ended() const { return world_->gameOver(); }
  /// True while the replay still has inputs.
  [[nodiscard]] bool playingBack() const { return run_ < config_.playback.size(); }
  /// Frames of replay input not yet played.
  [[nodiscard]] std::int64_t playbackLeft() const;
  /// The attempt being played: first_attempt at the start, one more at each restart().
  [[nodiscard]] int attempt() const { return attempt_; }
  /// The attempt's number at this scene, as the player counts: 1 at the start, one more at each
  /// restart(), whatever earlier games counted (attempt() continues theirs, for the recordings).
  [[nodiscard]] int sceneAttempt() const {
    return attempt_ - std::max(1, config_.first_attempt) + 1;
  }
  /// The file this attempt records to (empty when not recording).
  [[nodiscard]] const std::string& recordPath() const { return record_path_; }
  /// True when a recording is being written (not yet finished).
  [[nodiscard]] bool recording() const { return recorder_ != nullptr && !recording_done_; }
  /// Empty, or why the recording failed.
  [[nodiscard]] std::string recordError() const;
  /// The player's box before the last step.
  [[nodiscard]] const Obb2& previousBox() const { return previous_box_; }
  /// The player's box drawn at `alpha` in [0, 1] between the previous and the current step.
  [[nodiscard]] Obb2 blendedBox(double alpha) const;

 private:
  void startRecording();
  SessionConfig config_;
  std::unique_ptr<World> world_;
  std::unique_ptr<Recorder> recorder_;
  bool recording_done_ = false;
  std::string record_error_;
  int attempt_ = 1;
  std::string record_path_;      // this attempt's file
  std::size_t run_ = 0;          // playback run being played
  std::int64_t run_played_ = 0;  // frames of it already played
  Obb2 previous_box_;
};

/// Linear blend of two boxes: centres lerped, heading along the shorter arc (renormalised).
[[nodiscard]] Obb2 blendBoxes(const Obb2& a, const Obb2& b, double alpha);

}  // namespace cardemo
