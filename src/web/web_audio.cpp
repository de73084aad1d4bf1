#include "web/web_audio.hpp"

#include <emscripten/emscripten.h>

// clang-format off
EM_JS(void, cardemo_audio_loops, (double e0, double e1, double e2, double e3, double screech), {
  Module.page.audioLoops([e0, e1, e2, e3], screech);
});
EM_JS(void, cardemo_audio_once, (int sound, double level), {
  Module.page.audioOnce(sound, level);
});
// clang-format on

namespace cardemo {
namespace {

// The one-shot sounds, as page.js numbers them.
constexpr int kImpact = 0, kChime = 1;
// The chime's level, as the SDL window plays it (platform/game_audio.cpp).
constexpr double kChimeLevel = 0.8;

}  // namespace

void WebAudio::apply(const SoundFrame& frame, bool muted) {
  const double master = muted ? 0.0 : 1.0;
  cardemo_audio_loops(master * frame.engine[0], master * frame.engine[1], master * frame.engine[2],
                      master * frame.engine[3], master * frame.screech);
  if (!muted && frame.impact > 0.0) cardemo_audio_once(kImpact, frame.impact);
}

void WebAudio::playChime(bool muted) {
  if (!muted) cardemo_audio_once(kChime, kChimeLevel);
}

void WebAudio::silence() {
  cardemo_audio_loops(0.0, 0.0, 0.0, 0.0, 0.0);
}

}  // namespace cardemo
