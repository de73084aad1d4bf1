#include "platform/mixer_library.hpp"

#include <SDL.h>

namespace cardemo {
namespace {

// The runtime name first (what the linker would have recorded), then the development link.
constexpr const char* kNames[] = {"libSDL2_mixer-2.0.so.0", "libSDL2_mixer.so"};

struct Loaded {
  MixerLibrary functions;
  bool ok = false;
  std::string why;
};

template <typename F>
bool resolve(void* object, const char* name, F& out, std::string& why) {
  out = reinterpret_cast<F>(SDL_LoadFunction(object, name));
  if (out == nullptr && why.empty()) why = SDL_GetError();
  return out != nullptr;
}

Loaded load() {
  Loaded l;
  void* object = nullptr;
  for (const char* name : kNames) {
    object = SDL_LoadObject(name);
    if (object != nullptr) break;
  }
  if (object == nullptr) {
    l.why = std::string("cannot load SDL2_mixer: ") + SDL_GetError();
    return l;
  }
  MixerLibrary& m = l.functions;
  std::string why;
  // Every function is looked up, so `why` names the first one missing.
  bool ok = resolve(object, "Mix_OpenAudio", m.OpenAudio, why);
  ok = resolve(object, "Mix_CloseAudio", m.CloseAudio, why) && ok;
  ok = resolve(object, "Mix_QuerySpec", m.QuerySpec, why) && ok;
  ok = resolve(object, "Mix_LoadWAV", m.LoadWAV, why) && ok;
  ok = resolve(object, "Mix_FreeChunk", m.FreeChunk, why) && ok;
  ok = resolve(object, "Mix_AllocateChannels", m.AllocateChannels, why) && ok;
  ok = resolve(object, "Mix_ReserveChannels", m.ReserveChannels, why) && ok;
  ok = resolve(object, "Mix_GroupChannels", m.GroupChannels, why) && ok;
  ok = resolve(object, "Mix_GroupAvailable", m.GroupAvailable, why) && ok;
  ok = resolve(object, "Mix_GroupOldest", m.GroupOldest, why) && ok;
  ok = resolve(object, "Mix_Volume", m.Volume, why) && ok;
  ok = resolve(object, "Mix_PlayChannel", m.PlayChannel, why) && ok;
  ok = resolve(object, "Mix_HaltChannel", m.HaltChannel, why) && ok;
  if (!ok) {
    l.why = "SDL2_mixer: " + why;
    SDL_UnloadObject(object);
    return l;
  }
  l.ok = true;  // kept loaded until exit: chunks and the device may outlive any one caller
  return l;
}

}  // namespace

const MixerLibrary* mixerLibrary(std::string& why) {
  static const Loaded loaded = load();
  if (!loaded.ok) {
    why = loaded.why;
    return nullptr;
  }
  return &loaded.functions;
}

}  // namespace cardemo
