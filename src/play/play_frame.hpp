#pragma once
/// One drawn frame of a level as plain data: what a platform hands in (the actions, the
/// controller, the elapsed time, the window size) and what it must then carry out (draw, play,
/// window requests, leave).

#include <Eigen/Core>
#include <span>

#include "geometry/obb2.hpp"
#include "play/analog_drive.hpp"
#include "play/play_action.hpp"
#include "play/play_flow.hpp"
#include "play/sound_mix.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"

namespace cardemo {

/// What the platform measured and collected since the previous frame.
struct PlayInput {
  std::span<const PlayAction> actions;  ///< The frame's actions, in the order they happened.
  PadState pad;                         ///< The controller now (all zero without one).
  double elapsed_seconds = 0.0;         ///< Wall-clock seconds since the previous frame.
  Eigen::Vector2i viewport{1280, 720};  ///< Drawable size now, pixels.
};

/// What the platform does with one frame. When `exit` is not kStay there is nothing to draw or
/// play: the platform leaves the level and calls PlayScreen::finish().
struct PlayFrame {
  LevelExit exit = LevelExit::kStay;  ///< kStay, or where the player asked to go.
  int steps = 0;                      ///< Fixed steps simulated in this frame.

  const World* world = nullptr;  ///< The world to draw (valid until the next frame or restart).
  Camera camera;                 ///< The camera to draw it with.
  Obb2 player_box;               ///< The player's box, blended between the last two steps.
  DrawOptions draw;              ///< HUD, panels, banner, status, effects and goal.

  SoundFrame sound;    ///< The loops' levels and the impact to start (SoundMix).
  bool chime = false;  ///< The car parked in this frame: play the chime.
  bool muted = false;  ///< The player muted the sound (M).

  bool screenshot = false;         ///< Save the frame once drawn, then PlayScreen::showNote().
  bool toggle_fullscreen = false;  ///< Switch full screen on or off.
};

/// Draws `frame` (exit kStay) through drawFrame.
void drawPlayFrame(Canvas& canvas, const PlayFrame& frame);

}  // namespace cardemo
