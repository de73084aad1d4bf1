#include "platform/png_save.hpp"

#include <SDL_image.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cardemo {

std::string savePng(SDL_Surface* surface, const std::string& path) {
  if (surface == nullptr) return path + ": nothing to save";
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  if (IMG_SavePNG(surface, tmp.c_str()) != 0) {
    std::remove(tmp.c_str());
    return path + ": cannot write PNG: " + IMG_GetError();
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return path + ": cannot write: " + why;
  }
  return {};
}

std::string saveRendererPng(SDL_Renderer* renderer, const std::string& path) {
  int w = 0;
  int h = 0;
  if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0 || w <= 0 || h <= 0) {
    return path + ": cannot read the frame: " + SDL_GetError();
  }
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, w, h, 32, SDL_PIXELFORMAT_RGBA32);
  if (surface == nullptr) return path + ": out of memory for the screenshot";
  std::string why;
  if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGBA32, surface->pixels,
                           surface->pitch) != 0) {
    why = path + ": cannot read the frame: " + SDL_GetError();
  } else {
    why = savePng(surface, path);
  }
  SDL_FreeSurface(surface);
  return why;
}

}  // namespace cardemo
