#pragma once
/// The Canvas over an SDL_Renderer: polygons and thick lines through SDL_RenderGeometry, text
/// through SDL2_ttf.

#include <SDL.h>
#include <SDL_ttf.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace cardemo {

/// Draws on an SDL_Renderer (a window's or a software one). Does not own the renderer.
class SdlCanvas : public Canvas {
 public:
  /// Draws on `renderer` with text in the font at `font_path` (empty: findFontPath()). A missing
  /// font does not stop drawing: text is skipped and error() says why.
  explicit SdlCanvas(SDL_Renderer* renderer, const std::string& font_path = {});
  ~SdlCanvas() override;
  SdlCanvas(const SdlCanvas&) = delete;
  SdlCanvas& operator=(const SdlCanvas&) = delete;

  /// Loads the sprites (assets/sprites/car.png, wheel.png, ground.png, as scripts/make_sprites.py
  /// writes them, found with findAsset). Returns an empty string when all loaded, else one line
  /// naming what is missing; sprites that did load are used, the others fall back to vectors.
  std::string loadSprites();

  /// Empty, or why text cannot be drawn (font not found or not loadable).
  [[nodiscard]] const std::string& error() const { return error_; }

  [[nodiscard]] Eigen::Vector2i size() const override;
  void clear(const Rgba& color) override;
  void fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) override;
  void line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
            const Rgba& color) override;
  void text(const Eigen::Vector2f& top_left, std::string_view utf8, int pixel_height,
            const Rgba& color) override;
  [[nodiscard]] Eigen::Vector2f textSize(std::string_view utf8, int pixel_height) override;
  [[nodiscard]] bool hasImage(ImageId id) const override;
  void image(ImageId id, const Eigen::Vector2f& center, float angle, const Eigen::Vector2f& size,
             const Rgba& tint) override;

 private:
  struct CachedText {
    SDL_Texture* texture = nullptr;
    int w = 0, h = 0;
  };
  TTF_Font* font(int pixel_height);

  SDL_Renderer* renderer_;
  std::string font_path_;
  std::string error_;
  bool ttf_ready_ = false;
  std::map<int, TTF_Font*> fonts_;
  // Rendered white text by (size, string); tinted per draw with the texture's colour mod.
  std::map<std::pair<int, std::string>, CachedText> texts_;
  std::array<SDL_Texture*, kImageCount> images_{};
  std::vector<SDL_Vertex> vertices_;
  std::vector<int> indices_;
};

}  // namespace cardemo
