#pragma once
/// Samples held keys into one InputFrame per fixed step, so a press shorter than a step counts.

#include "sim/input_frame.hpp"

namespace cardemo {

/// The driving keys.
enum class DriveKey { kUp, kDown, kLeft, kRight, kHandbrake };

/// Collects key presses and releases between steps. sample() reports a key as held for the step if
/// it is held now or was pressed at any time since the previous sample. A key the last step saw
/// held that was released and pressed again since is reported up for this step and held from the
/// next: the simulation sees the fresh press (Down at a standstill reverses only on a new press).
class InputLatch {
 public:
  /// A key went down.
  void press(DriveKey key);
  /// A key went up.
  void release(DriveKey key);
  /// Releases everything (e.g. when the window loses focus).
  void releaseAll();
  /// The InputFrame for the next step; clears the "pressed since last sample" marks.
  [[nodiscard]] InputFrame sample();

 private:
  InputFrame held_;
  InputFrame pressed_since_sample_;
  InputFrame released_since_sample_;
  InputFrame repressed_;  // released and pressed again since the sample that reported it held
  InputFrame pending_;    // a press to report at the next sample (after a step reported it up)
  InputFrame reported_;   // what the last sample returned
};

}  // namespace cardemo
