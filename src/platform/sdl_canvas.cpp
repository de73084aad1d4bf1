#include "platform/sdl_canvas.hpp"

#include <SDL_image.h>

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"
#include "io/asset_lookup.hpp"
#include "platform/font_path.hpp"

namespace cardemo {
namespace {

// Text that changes every frame (frame numbers, FPS) would grow the cache without bound.
constexpr std::size_t kMaxCachedTexts = 512;
constexpr int kMinTextPx = 4;
constexpr int kMaxTextPx = 400;

SDL_Color sdlColor(const Rgba& c) {
  return {c.r, c.g, c.b, c.a};
}

}  // namespace

SdlCanvas::SdlCanvas(SDL_Renderer* renderer, const std::string& font_path)
    : renderer_(renderer), font_path_(font_path) {
  SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
  if (font_path_.empty()) {
    if (auto found = findFontPath(&error_)) font_path_ = *found;
  }
  if (!font_path_.empty()) {
    if (TTF_Init() == 0) {
      ttf_ready_ = true;
    } else {
      error_ = std::string("cannot start SDL2_ttf: ") + TTF_GetError();
    }
  }
}

SdlCanvas::~SdlCanvas() {
  for (SDL_Texture* t : images_) {
    if (t != nullptr) SDL_DestroyTexture(t);
  }
  for (auto& [key, t] : texts_) SDL_DestroyTexture(t.texture);
  for (auto& [size, f] : fonts_) {
    if (f != nullptr) TTF_CloseFont(f);
  }
  if (ttf_ready_) TTF_Quit();
}

Eigen::Vector2i SdlCanvas::size() const {
  int w = 0;
  int h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  return {w, h};
}

void SdlCanvas::clear(const Rgba& color) {
  SDL_SetRenderDrawColor(renderer_, color.r, color.g, color.b, color.a);
  SDL_RenderClear(renderer_);
}

void SdlCanvas::fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) {
  if (points.size() < 3) return;
  vertices_.clear();
  indices_.clear();
  const SDL_Color c = sdlColor(color);
  for (const Eigen::Vector2f& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    vertices_.push_back({{p.x(), p.y()}, c, {0.0f, 0.0f}});
  }
  // A triangle fan from the first point covers any convex polygon.
  for (int i = 1; i + 1 < static_cast<int>(points.size()); ++i) {
    indices_.insert(indices_.end(), {0, i, i + 1});
  }
  SDL_RenderGeometry(renderer_, nullptr, vertices_.data(), static_cast<int>(vertices_.size()),
                     indices_.data(), static_cast<int>(indices_.size()));
}

void SdlCanvas::line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
                     const Rgba& color) {
  const Eigen::Vector2f d = b - a;
  const float len = d.norm();
  if (!(len > 1e-6f)) return;
  const Eigen::Vector2f n =
      Eigen::Vector2f{-d.y(), d.x()} * (0.5f * std::max(thickness, 1.0f) / len);
  const std::array<Eigen::Vector2f, 4> quad{a + n, b + n, b - n, a - n};
  fillConvex(quad, color);
}

TTF_Font* SdlCanvas::font(int pixel_height) {
  if (!ttf_ready_) return nullptr;
  pixel_height = std::clamp(pixel_height, kMinTextPx, kMaxTextPx);
  auto it = fonts_.find(pixel_height);
  if (it != fonts_.end()) return it->second;
  TTF_Font* f = TTF_OpenFont(font_path_.c_str(), pixel_height);
  if (f == nullptr && error_.empty()) {
    error_ = "cannot load font " + font_path_ + ": " + TTF_GetError();
  }
  if (f != nullptr) TTF_SetFontHinting(f, TTF_HINTING_LIGHT);
  fonts_.emplace(pixel_height, f);
  return f;
}

void SdlCanvas::text(const Eigen::Vector2f& top_left, std::string_view utf8, int pixel_height,
                     const Rgba& color) {
  if (utf8.empty()) return;
  TTF_Font* f = font(pixel_height);
  if (f == nullptr) return;
  auto key = std::make_pair(pixel_height, std::string(utf8));
  auto it = texts_.find(key);
  if (it == texts_.end()) {
    if (texts_.size() >= kMaxCachedTexts) {
      for (auto& [k, t] : texts_) SDL_DestroyTexture(t.texture);
      texts_.clear();
    }
    SDL_Surface* surface = TTF_RenderUTF8_Blended(f, key.second.c_str(), {255, 255, 255, 255});
    if (surface == nullptr) return;
    CachedText cached{SDL_CreateTextureFromSurface(renderer_, surface), surface->w, surface->h};
    SDL_FreeSurface(surface);
    if (cached.texture == nullptr) return;
    SDL_SetTextureBlendMode(cached.texture, SDL_BLENDMODE_BLEND);
    it = texts_.emplace(std::move(key), cached).first;
  }
  const CachedText& t = it->second;
  SDL_SetTextureColorMod(t.texture, color.r, color.g, color.b);
  SDL_SetTextureAlphaMod(t.texture, color.a);
  const SDL_FRect dst{std::round(top_left.x()), std::round(top_left.y()), static_cast<float>(t.w),
                      static_cast<float>(t.h)};
  SDL_RenderCopyF(renderer_, t.texture, nullptr, &dst);
}

Eigen::Vector2f SdlCanvas::textSize(std::string_view utf8, int pixel_height) {
  TTF_Font* f = font(pixel_height);
  if (f == nullptr) {
    // Without a font, a fair estimate keeps the layout sensible.
    return {0.6f * pixel_height * static_cast<float>(utf8.size()), 1.2f * pixel_height};
  }
  int w = 0;
  int h = 0;
  TTF_SizeUTF8(f, std::string(utf8).c_str(), &w, &h);
  return {static_cast<float>(w), static_cast<float>(h)};
}

std::string SdlCanvas::loadSprites() {
  static constexpr std::array<const char*, kImageCount> kFiles{
      "sprites/car.png", "sprites/wheel.png", "sprites/ground.png"};
  std::string first_problem;
  int problems = 0;
  for (std::size_t i = 0; i < kFiles.size(); ++i) {
    if (images_[i] != nullptr) continue;
    std::string why;
    if (const std::optional<std::string> path = findAsset(kFiles[i], &why)) {
      if (SDL_Surface* surface = IMG_Load(path->c_str())) {
        images_[i] = SDL_CreateTextureFromSurface(renderer_, surface);
        SDL_FreeSurface(surface);
      }
      if (images_[i] == nullptr) why = *path + ": cannot load the sprite: " + IMG_GetError();
    }
    if (images_[i] == nullptr) {
      if (problems++ == 0) first_problem = why;
      continue;
    }
    SDL_SetTextureBlendMode(images_[i], SDL_BLENDMODE_BLEND);
    // Sprites are drawn smaller than they are stored: filter rather than drop texels.
    SDL_SetTextureScaleMode(images_[i], SDL_ScaleModeLinear);
  }
  if (problems > 1) first_problem += " (and " + std::to_string(problems - 1) + " more sprites)";
  return first_problem;
}

bool SdlCanvas::hasImage(ImageId id) const {
  return images_[static_cast<std::size_t>(id)] != nullptr;
}

void SdlCanvas::image(ImageId id, const Eigen::Vector2f& center, float angle,
                      const Eigen::Vector2f& size, const Rgba& tint) {
  SDL_Texture* t = images_[static_cast<std::size_t>(id)];
  if (t == nullptr || !center.allFinite() || !size.allFinite() || !std::isfinite(angle)) return;
  if (!(size.x() > 0.5f && size.y() > 0.5f)) return;
  SDL_SetTextureColorMod(t, tint.r, tint.g, tint.b);
  SDL_SetTextureAlphaMod(t, tint.a);
  const SDL_FRect dst{center.x() - 0.5f * size.x(), center.y() - 0.5f * size.y(), size.x(),
                      size.y()};
  SDL_RenderCopyExF(renderer_, t, nullptr, &dst, degreesFromRadians(static_cast<double>(angle)),
                    nullptr, SDL_FLIP_NONE);
}

}  // namespace cardemo
