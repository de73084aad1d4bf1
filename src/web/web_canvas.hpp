#pragma once
/// The Canvas of the page: draw calls are batched into one command list per frame, which the
/// page's script (site/page.js) replays on the HTML5 2D context in one call.

#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace cardemo {

/// Canvas over the page's `<canvas>` element. Nothing reaches the browser until flush().
class WebCanvas final : public Canvas {
 public:
  /// Reads the canvas element's size now (call at the start of each frame).
  void resize();
  /// Hands the frame's commands to the page and starts an empty list.
  void flush();

  /// Width and height in pixels, as of the last resize().
  [[nodiscard]] Eigen::Vector2i size() const override { return size_; }
  /// Fills everything with one colour.
  void clear(const Rgba& color) override;
  /// Fills a convex polygon (skipped when wholly off the canvas).
  void fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) override;
  /// A line segment `thickness` pixels wide.
  void line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
            const Rgba& color) override;
  /// One line of text, top-left at `top_left`.
  void text(const Eigen::Vector2f& top_left, std::string_view utf8, int pixel_height,
            const Rgba& color) override;
  /// True once the page has loaded the sprite.
  [[nodiscard]] bool hasImage(ImageId id) const override;
  /// A sprite, tinted, turned and scaled (skipped when wholly off the canvas).
  void image(ImageId id, const Eigen::Vector2f& center, float angle, const Eigen::Vector2f& size,
             const Rgba& tint) override;
  /// Size of a line of text, measured by the page (cached there).
  [[nodiscard]] Eigen::Vector2f textSize(std::string_view utf8, int pixel_height) override;

 private:
  void command(float op, const Rgba& color);
  [[nodiscard]] bool offCanvas(float min_x, float min_y, float max_x, float max_y) const;
  Eigen::Vector2i size_{1280, 720};
  std::vector<float> commands_;  // see site/page.js drawCommands() for the layout
  std::string texts_;            // the UTF-8 of every text command, back to back
};

}  // namespace cardemo
