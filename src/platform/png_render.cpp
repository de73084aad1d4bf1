#include "platform/png_render.hpp"

#include <SDL.h>

#include <memory>

#include "platform/png_save.hpp"
#include "platform/sdl_canvas.hpp"

namespace cardemo {

std::string renderPng(const World& world, const RenderSettings& settings, const std::string& out) {
  // A software renderer on a plain surface needs neither SDL_Init(SDL_INIT_VIDEO) nor a display.
  std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)> surface(
      SDL_CreateRGBSurfaceWithFormat(0, settings.width, settings.height, 32,
                                     SDL_PIXELFORMAT_RGBA32),
      &SDL_FreeSurface);
  if (!surface)
    return out + ": cannot create a " + std::to_string(settings.width) + "x" +
           std::to_string(settings.height) + " image: " + SDL_GetError();
  std::unique_ptr<SDL_Renderer, decltype(&SDL_DestroyRenderer)> renderer(
      SDL_CreateSoftwareRenderer(surface.get()), &SDL_DestroyRenderer);
  if (!renderer) return out + ": cannot create a software renderer: " + SDL_GetError();
  {
    SdlCanvas canvas(renderer.get());
    if (!canvas.error().empty()) return canvas.error();
    if (settings.options.sprites) {
      if (const std::string why = canvas.loadSprites(); !why.empty()) return why;
    }
    Camera camera =
        followCamera(world.carBox(), settings.pixels_per_metre, {settings.width, settings.height});
    if (settings.center) camera.center = *settings.center;
    if (settings.camera) camera = *settings.camera;
    drawFrame(canvas, world, camera, world.carBox(), settings.options, settings.palette);
    SDL_RenderPresent(renderer.get());
  }
  return savePng(surface.get(), out);
}

}  // namespace cardemo
