#pragma once
/// The drawing surface the renderer draws through; SDL implements it in src/platform/.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string_view>

namespace cardemo {

/// 8-bit RGBA colour.
struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;  ///< Channels, 0..255.
  /// Bitwise equality.
  [[nodiscard]] bool operator==(const Rgba&) const = default;
};

/// The sprites a canvas may hold (assets/sprites/*.png, drawn by scripts/make_sprites.py).
enum class ImageId : std::uint8_t {
  kCarBody,  ///< A car seen from above, nose towards +x, light grey so a tint colours it.
  kWheel,    ///< One tyre seen from above, rolling direction along +x.
  kGround,   ///< A seamless asphalt tile.
};

/// Number of ImageId values.
inline constexpr int kImageCount = 3;

/// Abstract 2D canvas in pixels: origin at the top-left, y down.
class Canvas {
 public:
  virtual ~Canvas() = default;
  /// Width and height in pixels.
  [[nodiscard]] virtual Eigen::Vector2i size() const = 0;
  /// Fills everything with one colour.
  virtual void clear(const Rgba& color) = 0;
  /// Fills a convex polygon given in pixel coordinates (any winding, 3 or more points).
  virtual void fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) = 0;
  /// Draws a line segment `thickness` pixels wide.
  virtual void line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
                    const Rgba& color) = 0;
  /// Draws one line of UTF-8 text with its top-left corner at `top_left`.
  virtual void text(const Eigen::Vector2f& top_left, std::string_view utf8, int pixel_height,
                    const Rgba& color) = 0;
  /// True when image() can draw `id` (the sprite was found and loaded).
  [[nodiscard]] virtual bool hasImage(ImageId id) const = 0;
  /// Draws image `id` scaled to `size` pixels, centred at `center`, turned by `angle` radians
  /// clockwise on screen (screen y points down), each texel multiplied by `tint` (RGB and alpha).
  /// Does nothing when hasImage(id) is false.
  virtual void image(ImageId id, const Eigen::Vector2f& center, float angle,
                     const Eigen::Vector2f& size, const Rgba& tint) = 0;
  /// Size in pixels that text() would cover.
  [[nodiscard]] virtual Eigen::Vector2f textSize(std::string_view utf8, int pixel_height) = 0;
};

}  // namespace cardemo
