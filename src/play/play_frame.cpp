#include "play/play_frame.hpp"

#include <cassert>

namespace cardemo {

void drawPlayFrame(Canvas& canvas, const PlayFrame& frame) {
  assert(frame.world != nullptr);
  drawFrame(canvas, *frame.world, frame.camera, frame.player_box, frame.draw);
}

}  // namespace cardemo
