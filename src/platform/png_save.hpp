#pragma once
/// Saving SDL pixels as PNG files, atomically (encoded in memory, then io/atomic_file).

#include <SDL.h>

#include <string>

namespace cardemo {

/// Writes `surface` to `path` as PNG with writeFileAtomically (temporary file, fsync, rename), so a
/// reader never sees a half-written file. Returns an empty string on success, else one sentence
/// naming `path` and what went wrong.
[[nodiscard]] std::string savePng(SDL_Surface* surface, const std::string& path);

/// Reads back what `renderer` has drawn (e.g. a window's frame before SDL_RenderPresent, for F12)
/// and saves it with savePng.
[[nodiscard]] std::string saveRendererPng(SDL_Renderer* renderer, const std::string& path);

}  // namespace cardemo
