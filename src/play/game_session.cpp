#include "play/game_session.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cardemo {

GameSession::GameSession(SessionConfig config)
    : config_(std::move(config)), attempt_(std::max(1, config_.first_attempt)) {
  if (config_.flush_every_frames <= 0) {
    config_.flush_every_frames = static_cast<std::int64_t>(std::ceil(config_.settings.hz));
  }
  world_ = std::make_unique<World>(config_.scene, config_.settings);
  previous_box_ = world_->carBox();
  startRecording();
}

void GameSession::startRecording() {
  if (config_.record_path.empty()) return;
  record_path_ = attemptPath(config_.record_path, attempt_);
  recorder_ = std::make_unique<Recorder>(record_path_, config_.scene_path,
                                         static_cast<int>(std::lround(config_.settings.hz)),
                                         config_.flush_every_frames);
  recording_done_ = false;
}

InputFrame GameSession::step(const InputFrame& live) {
  if (world_->gameOver()) return {};
  InputFrame input = live;
  if (playingBack()) {
    input = config_.playback[run_].keys;
    if (++run_played_ >= config_.playback[run_].count) {
      ++run_;
      run_played_ = 0;
    }
  }
  previous_box_ = world_->carBox();
  world_->step(input);
  if (recording()) recorder_->record(input);
  // The recording ends where the game does, so it replays to the same outcome.
  if (world_->gameOver()) (void)finishRecording();
  return input;
}

void GameSession::restart() {
  (void)finishRecording();
  world_ = std::make_unique<World>(config_.scene, config_.settings);
  previous_box_ = world_->carBox();
  run_ = 0;
  run_played_ = 0;
  recorder_.reset();
  record_error_.clear();
  ++attempt_;
  startRecording();
}

std::string GameSession::finishRecording() {
  if (recorder_ == nullptr || recording_done_) return record_error_;
  recording_done_ = true;
  record_error_ = recorder_->finish();
  return record_error_;
}

std::int64_t GameSession::playbackLeft() const {
  std::int64_t left = 0;
  for (std::size_t i = run_; i < config_.playback.size(); ++i) left += config_.playback[i].count;
  return left - run_played_;
}

std::string GameSession::recordError() const {
  if (!record_error_.empty()) return record_error_;
  return recorder_ ? recorder_->error() : std::string();
}

Obb2 GameSession::blendedBox(double alpha) const {
  return blendBoxes(previous_box_, world_->carBox(), alpha);
}

Obb2 blendBoxes(const Obb2& a, const Obb2& b, double alpha) {
  Obb2 out = b;
  out.center = a.center + (b.center - a.center) * alpha;
  Eigen::Vector2d axis = a.axis + (b.axis - a.axis) * alpha;
  const double n = axis.norm();
  // Opposite axes (a half turn in one step) have no midpoint: keep the newer one.
  out.axis = n > 1e-9 ? Eigen::Vector2d(axis / n) : b.axis;
  return out;
}

}  // namespace cardemo
