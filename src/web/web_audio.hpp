#pragma once
/// The game's sound in the page: the frame's levels handed to Web Audio (site/page.js), which
/// plays the same WAVs as the SDL window with the same mix (platform/game_audio).

#include "play/sound_mix.hpp"

namespace cardemo {

/// Carries SoundFrames out through the page's Web Audio graph.
class WebAudio {
 public:
  /// The loops' levels, and the impact to start, of one frame; all silent when `muted`.
  void apply(const SoundFrame& frame, bool muted);
  /// The parking chime (not when muted).
  void playChime(bool muted);
  /// Every loop silent (the game left the level).
  void silence();
};

}  // namespace cardemo
