#pragma once
/// The game's sound through SDL2_mixer: engine loops, tyre screech, impacts and the parked chime.
/// What to play is decided in src/play/sound_mix; this only carries it out.

#include <array>
#include <string>

#include "play/sound_mix.hpp"

struct Mix_Chunk;

namespace cardemo {

struct MixerLibrary;

/// Owns the audio device and the loaded sounds. Without an audio device (no sound card, under Xvfb,
/// in CI) or without the sound files the game runs silently: every call is then harmless.
class GameAudio {
 public:
  /// Opens the device and loads the WAVs from `folder` (assets/sounds). `muted`: start silent (the
  /// M key toggles). When sound cannot be had, message() says why.
  GameAudio(const std::string& folder, bool muted);
  ~GameAudio();
  GameAudio(const GameAudio&) = delete;
  GameAudio& operator=(const GameAudio&) = delete;

  /// True when sound is playing (a device is open and the sounds are loaded).
  [[nodiscard]] bool available() const { return open_; }
  /// Empty, or one sentence on why the game is silent.
  [[nodiscard]] const std::string& message() const { return message_; }
  /// Sets the loops' levels and starts the frame's impact, if any.
  void apply(const SoundFrame& frame);
  /// The parked chime (for the parking goal to call when the car comes to rest in the bay).
  void playChime();
  /// M: sound off / on.
  void toggleMute() { muted_ = !muted_; }
  /// True while muted.
  [[nodiscard]] bool muted() const { return muted_; }

 private:
  void playOnce(Mix_Chunk* chunk, double level);
  const MixerLibrary* mix_ = nullptr;  // set once SDL2_mixer is loaded
  bool open_ = false;
  bool muted_ = false;
  std::string message_;
  std::array<Mix_Chunk*, kEngineLoops> engine_{};
  Mix_Chunk* screech_ = nullptr;
  Mix_Chunk* impact_ = nullptr;
  Mix_Chunk* chime_ = nullptr;
};

}  // namespace cardemo
