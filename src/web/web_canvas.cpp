#include "web/web_canvas.hpp"

#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>

// The page's side of the canvas (site/page.js, Module.page).
// clang-format off
EM_JS(int, cardemo_canvas_width, (), { return Module.page.canvasWidth(); });
EM_JS(int, cardemo_canvas_height, (), { return Module.page.canvasHeight(); });
EM_JS(void, cardemo_canvas_draw, (const float* commands, int count, const char* texts, int length), {
  Module.page.drawCommands(HEAPF32.subarray(commands >> 2, (commands >> 2) + count),
                           HEAPU8.subarray(texts, texts + length));
});
EM_JS(float, cardemo_text_width, (const char* utf8, int length, int pixel_height), {
  return Module.page.textWidth(UTF8ToString(utf8, length), pixel_height);
});
EM_JS(float, cardemo_text_height, (int pixel_height), {
  return Module.page.textHeight(pixel_height);
});
EM_JS(int, cardemo_has_image, (int id), { return Module.page.hasImage(id) ? 1 : 0; });
// clang-format on

namespace cardemo {
namespace {

// Command codes, read by page.js.
constexpr float kClear = 0, kFill = 1, kLine = 2, kText = 3, kImage = 4;

}  // namespace

void WebCanvas::resize() {
  size_ = {cardemo_canvas_width(), cardemo_canvas_height()};
}

void WebCanvas::flush() {
  cardemo_canvas_draw(commands_.data(), static_cast<int>(commands_.size()), texts_.data(),
                      static_cast<int>(texts_.size()));
  commands_.clear();
  texts_.clear();
}

void WebCanvas::command(float op, const Rgba& color) {
  commands_.insert(commands_.end(), {op, static_cast<float>(color.r), static_cast<float>(color.g),
                                     static_cast<float>(color.b), static_cast<float>(color.a)});
}

bool WebCanvas::offCanvas(float min_x, float min_y, float max_x, float max_y) const {
  return max_x < 0.0f || max_y < 0.0f || min_x > static_cast<float>(size_.x()) ||
         min_y > static_cast<float>(size_.y());
}

void WebCanvas::clear(const Rgba& color) {
  commands_.clear();
  texts_.clear();
  command(kClear, color);
}

void WebCanvas::fillConvex(std::span<const Eigen::Vector2f> points, const Rgba& color) {
  if (points.size() < 3 || color.a == 0) return;
  Eigen::Vector2f lo = points[0], hi = points[0];
  for (const Eigen::Vector2f& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (offCanvas(lo.x(), lo.y(), hi.x(), hi.y())) return;
  command(kFill, color);
  commands_.push_back(static_cast<float>(points.size()));
  for (const Eigen::Vector2f& p : points) commands_.insert(commands_.end(), {p.x(), p.y()});
}

void WebCanvas::line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
                     const Rgba& color) {
  if (!a.allFinite() || !b.allFinite() || color.a == 0) return;
  const float pad = 0.5f * std::max(thickness, 1.0f);
  if (offCanvas(std::min(a.x(), b.x()) - pad, std::min(a.y(), b.y()) - pad,
                std::max(a.x(), b.x()) + pad, std::max(a.y(), b.y()) + pad)) {
    return;
  }
  command(kLine, color);
  commands_.insert(commands_.end(), {std::max(thickness, 1.0f), a.x(), a.y(), b.x(), b.y()});
}

void WebCanvas::text(const Eigen::Vector2f& top_left, std::string_view utf8, int pixel_height,
                     const Rgba& color) {
  if (utf8.empty() || !top_left.allFinite()) return;
  command(kText, color);
  commands_.insert(
      commands_.end(),
      {std::round(top_left.x()), std::round(top_left.y()), static_cast<float>(pixel_height),
       static_cast<float>(texts_.size()), static_cast<float>(utf8.size())});
  texts_.append(utf8);
}

bool WebCanvas::hasImage(ImageId id) const {
  return cardemo_has_image(static_cast<int>(id)) != 0;
}

void WebCanvas::image(ImageId id, const Eigen::Vector2f& center, float angle,
                      const Eigen::Vector2f& size, const Rgba& tint) {
  if (!center.allFinite() || !size.allFinite() || !std::isfinite(angle)) return;
  const float reach = 0.5f * size.norm();  // the turned sprite stays within this radius
  if (offCanvas(center.x() - reach, center.y() - reach, center.x() + reach, center.y() + reach)) {
    return;
  }
  command(kImage, tint);
  commands_.insert(commands_.end(),
                   {static_cast<float>(id), center.x(), center.y(), angle, size.x(), size.y()});
}

Eigen::Vector2f WebCanvas::textSize(std::string_view utf8, int pixel_height) {
  return {cardemo_text_width(utf8.data(), static_cast<int>(utf8.size()), pixel_height),
          cardemo_text_height(pixel_height)};
}

}  // namespace cardemo
