#pragma once
/// SDL2_mixer, loaded when the game first opens sound (SDL_LoadObject) instead of linked: the
/// headless commands never play a sound, and loading the mixer with its codecs (and running their
/// initialisers) cost every `cardemo` start about 20 million instructions.

#include <SDL_mixer.h>

#include <string>

namespace cardemo {

/// The SDL2_mixer functions the game calls.
struct MixerLibrary {
  decltype(&Mix_OpenAudio) OpenAudio = nullptr;                ///< Mix_OpenAudio
  decltype(&Mix_CloseAudio) CloseAudio = nullptr;              ///< Mix_CloseAudio
  decltype(&Mix_QuerySpec) QuerySpec = nullptr;                ///< Mix_QuerySpec
  decltype(&Mix_LoadWAV) LoadWAV = nullptr;                    ///< Mix_LoadWAV
  decltype(&Mix_FreeChunk) FreeChunk = nullptr;                ///< Mix_FreeChunk
  decltype(&Mix_AllocateChannels) AllocateChannels = nullptr;  ///< Mix_AllocateChannels
  decltype(&Mix_ReserveChannels) ReserveChannels = nullptr;    ///< Mix_ReserveChannels
  decltype(&Mix_GroupChannels) GroupChannels = nullptr;        ///< Mix_GroupChannels
  decltype(&Mix_GroupAvailable) GroupAvailable = nullptr;      ///< Mix_GroupAvailable
  decltype(&Mix_GroupOldest) GroupOldest = nullptr;            ///< Mix_GroupOldest
  decltype(&Mix_Volume) Volume = nullptr;                      ///< Mix_Volume
  decltype(&Mix_PlayChannel) PlayChannel = nullptr;            ///< Mix_PlayChannel
  decltype(&Mix_HaltChannel) HaltChannel = nullptr;            ///< Mix_HaltChannel
};

/// The mixer, loaded on the first call and kept until exit; null when it cannot be loaded or lacks
/// a function, and `why` then says why.
[[nodiscard]] const MixerLibrary* mixerLibrary(std::string& why);

}  // namespace cardemo
