#include "platform/game_audio.hpp"

#include <SDL.h>
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "platform/mixer_library.hpp"

namespace cardemo {
namespace {

// Channels 0..3 hold the engine loops and 4 the screech loop, reserved so that one-shots
// (impacts, the chime) never take them; one-shots get the channels above.
constexpr int kScreechChannel = static_cast<int>(kEngineLoops);
constexpr int kLoopChannels = kScreechChannel + 1;
constexpr int kChannels = kLoopChannels + 4;
constexpr int kOneShotGroup = 1;

// libasound prints a screenful to stderr when there is no sound card (as under Xvfb and in CI)
// before SDL reports the failure; the game says it once itself, so stderr is muted meanwhile.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) (void)::dup2(null, STDERR_FILENO);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ < 0) return;
    (void)::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

// Loads the mixer and opens the device with the library's own complaints silenced; empty or why
// it failed. `mix` is set once the mixer is loaded.
std::string openDevice(const MixerLibrary*& mix) {
  const QuietStderr quiet;
  std::string why;
  mix = mixerLibrary(why);
  if (mix == nullptr) return why;
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) return SDL_GetError();
  if (mix->OpenAudio(22050, AUDIO_S16SYS, 2, 1024) != 0) {
    std::string why = Mix_GetError();
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return why;
  }
  return {};
}

int volume(double level) {
  const double clamped = std::isnan(level) ? 0.0 : std::fmin(1.0, std::fmax(0.0, level));
  return static_cast<int>(std::lround(clamped * MIX_MAX_VOLUME));
}

}  // namespace

GameAudio::GameAudio(const std::string& folder, bool muted) : muted_(muted) {
  if (folder.empty()) {
    message_ = "cannot find the sounds folder (assets/sounds): playing without sound";
    return;
  }
  if (const std::string why = openDevice(mix_); !why.empty()) {
    message_ = "no audio device (" + why + "): playing without sound";
    return;
  }
  const auto load = [&](const std::string& name) -> Mix_Chunk* {
    Mix_Chunk* chunk = mix_->LoadWAV((folder + "/" + name).c_str());
    if (chunk == nullptr && message_.empty()) {
      message_ = folder + "/" + name + ": cannot load (" + Mix_GetError() +
                 "): playing without sound (scripts/make_sounds.py makes the sounds)";
    }
    return chunk;
  };
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    engine_[i] = load("engine-" + std::to_string(i + 1) + ".wav");
  }
  screech_ = load("screech.wav");
  impact_ = load("impact.wav");
  chime_ = load("chime.wav");
  if (!message_.empty()) return;  // the destructor frees what was loaded
  open_ = true;
  mix_->AllocateChannels(kChannels);
  mix_->ReserveChannels(kLoopChannels);
  mix_->GroupChannels(kLoopChannels, kChannels - 1, kOneShotGroup);
  // The loops run all the time at volume 0; apply() only moves their levels.
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    mix_->Volume(static_cast<int>(i), 0);
    mix_->PlayChannel(static_cast<int>(i), engine_[i], -1);
  }
  mix_->Volume(kScreechChannel, 0);
  mix_->PlayChannel(kScreechChannel, screech_, -1);
}

GameAudio::~GameAudio() {
  if (mix_ == nullptr || SDL_WasInit(SDL_INIT_AUDIO) == 0) return;
  const bool mixer_open = mix_->QuerySpec(nullptr, nullptr, nullptr) != 0;
  if (mixer_open) mix_->HaltChannel(-1);
  for (Mix_Chunk* chunk : engine_) mix_->FreeChunk(chunk);
  for (Mix_Chunk* chunk : {screech_, impact_, chime_}) mix_->FreeChunk(chunk);
  if (mixer_open) mix_->CloseAudio();
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void GameAudio::apply(const SoundFrame& frame) {
  if (!open_) return;
  const double master = muted_ ? 0.0 : 1.0;
  for (std::size_t i = 0; i < kEngineLoops; ++i) {
    mix_->Volume(static_cast<int>(i), volume(master * frame.engine[i]));
  }
  mix_->Volume(kScreechChannel, volume(master * frame.screech));
  if (frame.impact > 0.0) playOnce(impact_, frame.impact);
}

void GameAudio::playChime() {
  playOnce(chime_, 0.8);
}

void GameAudio::playOnce(Mix_Chunk* chunk, double level) {
  if (!open_ || muted_ || chunk == nullptr) return;
  // The volume first, so not one sample plays at a channel's previous level; when every channel
  // is busy the oldest one-shot gives way.
  int channel = mix_->GroupAvailable(kOneShotGroup);
  if (channel < 0) channel = mix_->GroupOldest(kOneShotGroup);
  if (channel < 0) return;
  mix_->Volume(channel, volume(level));
  mix_->PlayChannel(channel, chunk, 0);
}

}  // namespace cardemo
