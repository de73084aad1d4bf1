#include "platform/png_save.hpp"

#include <SDL_image.h>

#include <algorithm>
#include <cstring>

#include "io/atomic_file.hpp"

namespace cardemo {
namespace {

// SDL2 has no growable memory stream: this SDL_RWops writes into a std::string, so the PNG can be
// encoded in memory and then written like every other output file (io/atomic_file: temporary file,
// fsync, rename).
struct MemoryFile {
  std::string bytes;
  std::size_t at = 0;
};

MemoryFile& memoryOf(SDL_RWops* rw) {
  return *static_cast<MemoryFile*>(rw->hidden.unknown.data1);
}

Sint64 memorySize(SDL_RWops* rw) {
  return static_cast<Sint64>(memoryOf(rw).bytes.size());
}

Sint64 memorySeek(SDL_RWops* rw, Sint64 offset, int whence) {
  MemoryFile& m = memoryOf(rw);
  const Sint64 base = whence == RW_SEEK_CUR   ? static_cast<Sint64>(m.at)
                      : whence == RW_SEEK_END ? static_cast<Sint64>(m.bytes.size())
                                              : 0;
  if (base + offset < 0) return SDL_SetError("seek before the start of the PNG buffer");
  m.at = static_cast<std::size_t>(base + offset);
  return static_cast<Sint64>(m.at);
}

std::size_t memoryRead(SDL_RWops* rw, void* out, std::size_t size, std::size_t count) {
  MemoryFile& m = memoryOf(rw);
  if (size == 0 || m.at >= m.bytes.size()) return 0;
  const std::size_t n = std::min(count, (m.bytes.size() - m.at) / size);
  std::memcpy(out, m.bytes.data() + m.at, n * size);
  m.at += n * size;
  return n;
}

std::size_t memoryWrite(SDL_RWops* rw, const void* in, std::size_t size, std::size_t count) {
  MemoryFile& m = memoryOf(rw);
  const std::size_t n = size * count;
  if (m.bytes.size() < m.at + n) m.bytes.resize(m.at + n);
  std::memcpy(m.bytes.data() + m.at, in, n);
  m.at += n;
  return count;
}

int memoryClose(SDL_RWops* rw) {
  SDL_FreeRW(rw);
  return 0;
}

}  // namespace

std::string savePng(SDL_Surface* surface, const std::string& path) {
  if (surface == nullptr) return path + ": nothing to save";
  MemoryFile memory;
  SDL_RWops* rw = SDL_AllocRW();
  if (rw == nullptr) return path + ": out of memory for the PNG";
  rw->size = memorySize;
  rw->seek = memorySeek;
  rw->read = memoryRead;
  rw->write = memoryWrite;
  rw->close = memoryClose;
  rw->hidden.unknown.data1 = &memory;
  const bool encoded = IMG_SavePNG_RW(surface, rw, 1) == 0;  // 1: closes (frees) rw
  if (!encoded) return path + ": cannot encode PNG: " + IMG_GetError();
  return writeFileAtomically(path, memory.bytes);
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
