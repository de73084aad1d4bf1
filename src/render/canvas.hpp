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
  /// Size in pixels that text() would cover.
  [[nodiscard]] virtual Eigen::Vector2f textSize(std::string_view utf8, int pixel_height) = 0;
};

}  // namespace cardemo
