#pragma once
// Drives a PlayScreen as a platform does (actions, elapsed time, a window size), and the small
// scenes its tests play.

#include <string>
#include <utility>
#include <vector>

#include "../sim/scene_builders.hpp"
#include "play/play_screen.hpp"

namespace cardemo::test {

inline constexpr double kStep = 1.0 / 120.0;  // one fixed step at the default 120 Hz

/// A PlayScreen and the actions of its current frame.
class ScreenDriver {
 public:
  explicit ScreenDriver(PlayScreenConfig config) : screen_(std::move(config)) {}

  /// One frame with `actions` and `elapsed` seconds (no controller, a 1280x720 window).
  const PlayFrame& frame(std::vector<PlayAction> actions = {}, double elapsed = 0.0) {
    actions_ = std::move(actions);
    return screen_.frame({actions_, PadState{}, elapsed, {1280, 720}});
  }
  /// One frame with a single action.
  const PlayFrame& act(PlayActionKind kind, double elapsed = 0.0) {
    return frame({PlayAction{kind}}, elapsed);
  }
  /// Frames of one step each until the run has ended (at most `max_frames`).
  void runToEnd(int max_frames = 2000) {
    for (int i = 0; i < max_frames && !ended(); ++i) (void)frame({}, kStep);
  }
  /// The run has ended (GAME OVER, PARKED, TIME UP).
  [[nodiscard]] bool ended() const { return screen_.ended(); }
  /// The screen.
  PlayScreen& screen() { return screen_; }
  /// The world's frame.
  [[nodiscard]] std::int64_t worldFrame() const { return screen_.session().world().frame(); }

 private:
  PlayScreen screen_;
  std::vector<PlayAction> actions_;
};

/// A driving key pressed.
inline PlayAction press(DriveKey key) {
  return {PlayActionKind::kDrivePress, key};
}

/// A driving key released.
inline PlayAction release(DriveKey key) {
  return {PlayActionKind::kDriveRelease, key};
}

/// A config for `scene` with sound available and nothing written.
inline PlayScreenConfig screenConfig(Scene scene) {
  PlayScreenConfig config;
  config.session.scene_path = "scene.json";
  config.session.scene = std::move(scene);
  return config;
}

/// An open floor: no walls, no cars, no goal; nothing ends the run.
inline Scene openFloor(double speed = 0.0) {
  Scene s = sceneWith({});
  s.name = "open";
  s.player.speed = speed;
  return s;
}

/// A level: the car rolls at 1 m/s towards a bay 0.5 m ahead and parks when braked (Down held).
inline Scene rollInLevel() {
  Scene s = sceneWith({});
  s.name = "roll-in";
  s.player.speed = 1.0;
  Goal goal;
  goal.bay.center = {0.5, 0.0};
  goal.hold_time = 0.0;
  s.goal = goal;
  return s;
}

/// 12 m/s at a car 9 m ahead with 5 health: the first hit ends the game.
inline Scene crashScene() {
  Scene s = sceneWith({parkedCar("wall", 9.0, 0.0, 90.0)});
  s.name = "crash";
  s.player.speed = 12.0;
  s.player.health = 5;
  return s;
}

}  // namespace cardemo::test
