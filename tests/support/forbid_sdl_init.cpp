/// LD_PRELOAD shim for the headless tests: any attempt to initialise SDL (video or any other
/// subsystem) ends the process with status 86 and a message, so a headless command that starts SDL
/// fails its test. Deliberately does not include SDL: it only has to interpose the symbols.

#include <unistd.h>

#include <cstring>

namespace {

[[noreturn]] void refuse(const char* function) {
  const char* prefix = "forbid_sdl_init: headless mode called ";
  (void)!::write(2, prefix, std::strlen(prefix));
  (void)!::write(2, function, std::strlen(function));
  (void)!::write(2, "\n", 1);
  ::_exit(86);
}

}  // namespace

// The signatures are SDL2's (Uint32 flags, const char* driver); the values are never used.
extern "C" int SDL_Init(unsigned /*flags*/) {
  refuse("SDL_Init");
}
extern "C" int SDL_InitSubSystem(unsigned /*flags*/) {
  refuse("SDL_InitSubSystem");
}
extern "C" int SDL_VideoInit(const char* /*driver*/) {
  refuse("SDL_VideoInit");
}
