#pragma once
/// A Canvas that records every call, for checking what the renderer draws without SDL.

#include <string>
#include <vector>

#include "render/canvas.hpp"

namespace cardemo::test {

/// Records polygons, lines and text; text is sized as 0.6 em per character.
class RecordingCanvas : public Canvas {
 public:
  /// A filled polygon.
  struct Fill {
    std::vector<Eigen::Vector2f> points;  ///< Pixels.
    Rgba color;                           ///< Fill colour.
    int order;                            ///< Place among the fills, lines and texts, from 0.
    /// Mean of the points.
    [[nodiscard]] Eigen::Vector2f centroid() const {
      Eigen::Vector2f c = Eigen::Vector2f::Zero();
      for (const auto& p : points) c += p;
      return c / static_cast<float>(points.size());
    }
    /// Width of the points' bounding box.
    [[nodiscard]] float width() const {
      float lo = points[0].x(), hi = points[0].x();
      for (const auto& p : points) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
      return hi - lo;
    }
  };
  /// A line segment.
  struct Line {
    Eigen::Vector2f a, b;  ///< Ends, pixels.
    float thickness;       ///< Pixels.
    Rgba color;            ///< Colour.
    int order;             ///< Place among the fills, lines and texts, from 0.
  };
  /// A text call.
  struct Text {
    Eigen::Vector2f at;  ///< Top-left, pixels.
    std::string text;    ///< UTF-8.
    Rgba color;          ///< Colour.
    int order;           ///< Place among the fills, lines and texts, from 0.
  };

  /// An image call.
  struct Image {
    ImageId id;              ///< Which sprite.
    Eigen::Vector2f center;  ///< Pixels.
    float angle;             ///< Radians, clockwise on screen.
    Eigen::Vector2f size;    ///< Pixels.
    Rgba tint;               ///< Colour multiplier.
  };

  explicit RecordingCanvas(Eigen::Vector2i size = {1280, 720}) : size_(size) {}
  [[nodiscard]] Eigen::Vector2i size() const override { return size_; }
  void clear(const Rgba& color) override {
    cleared = color;
    fills.clear();
    lines.clear();
    texts.clear();
    images.clear();
    calls_ = 0;
  }
  void fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) override {
    fills.push_back({{points.begin(), points.end()}, color, calls_++});
  }
  void line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
            const Rgba& color) override {
    lines.push_back({a, b, thickness, color, calls_++});
  }
  void text(const Eigen::Vector2f& top_left, std::string_view utf8, int,
            const Rgba& color) override {
    texts.push_back({top_left, std::string(utf8), color, calls_++});
  }
  [[nodiscard]] bool hasImage(ImageId) const override { return with_images; }
  void image(ImageId id, const Eigen::Vector2f& center, float angle, const Eigen::Vector2f& size,
             const Rgba& tint) override {
    if (with_images) images.push_back({id, center, angle, size, tint});
  }
  [[nodiscard]] Eigen::Vector2f textSize(std::string_view utf8, int pixel_height) override {
    return {0.6f * pixel_height * static_cast<float>(utf8.size()), 1.2f * pixel_height};
  }

  /// Fills of one colour.
  [[nodiscard]] std::vector<Fill> fillsOf(const Rgba& color) const {
    std::vector<Fill> out;
    for (const Fill& f : fills) {
      if (f.color == color) out.push_back(f);
    }
    return out;
  }
  /// Image calls of one sprite.
  [[nodiscard]] std::vector<Image> imagesOf(ImageId id) const {
    std::vector<Image> out;
    for (const Image& i : images) {
      if (i.id == id) out.push_back(i);
    }
    return out;
  }
  /// Lines of one colour.
  [[nodiscard]] std::size_t linesOf(const Rgba& color) const {
    std::size_t n = 0;
    for (const Line& l : lines) n += l.color == color ? 1 : 0;
    return n;
  }
  /// The last text call that contains `needle`, or null.
  [[nodiscard]] const Text* lastText(const std::string& needle) const {
    for (auto it = texts.rbegin(); it != texts.rend(); ++it) {
      if (it->text.find(needle) != std::string::npos) return &*it;
    }
    return nullptr;
  }
  /// True when some text call contains `needle`.
  [[nodiscard]] bool hasText(const std::string& needle) const {
    for (const Text& t : texts) {
      if (t.text.find(needle) != std::string::npos) return true;
    }
    return false;
  }

  /// The text drawn on the same row as the text `label` (to its right), or "" without one.
  [[nodiscard]] std::string rowValue(const std::string& label) const {
    for (const Text& t : texts) {
      if (t.text != label) continue;
      for (const Text& v : texts) {
        if (&v != &t && v.at.y() == t.at.y() && v.at.x() > t.at.x()) return v.text;
      }
    }
    return "";
  }

  Rgba cleared;               ///< Last clear colour.
  std::vector<Fill> fills;    ///< Since the last clear.
  std::vector<Line> lines;    ///< Since the last clear.
  std::vector<Text> texts;    ///< Since the last clear.
  std::vector<Image> images;  ///< Since the last clear.
  bool with_images = false;   ///< What hasImage() answers (set it to test sprite drawing).

 private:
  Eigen::Vector2i size_;
  int calls_ = 0;
};

}  // namespace cardemo::test
