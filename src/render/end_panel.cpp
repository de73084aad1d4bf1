#include "render/end_panel.hpp"

#include <algorithm>
#include <cmath>

#include "render/hud.hpp"
#include "render/hud_colors.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

using hud_colors::kDim;
using hud_colors::kText;

struct Metrics {
  float scale, pad;
  int big, small;
};

Metrics metrics(const Canvas& canvas) {
  const float s = hudScale(canvas.size());
  return {s, 14.0f * s, static_cast<int>(std::lround(34.0f * s)),
          static_cast<int>(std::lround(17.0f * s))};
}

std::vector<HudRow> tableRows(const EndPanel& panel) {
  std::vector<HudRow> rows;
  for (const auto& [label, value] : panel.rows) rows.push_back({label, value, kText});
  return rows;
}

}  // namespace

Eigen::Vector2f placeBeside(const Eigen::Vector2i& viewport, const Eigen::Vector2f& car_min,
                            const Eigen::Vector2f& car_max, const Eigen::Vector2f& panel,
                            float gap) {
  const Eigen::Vector2f vp = viewport.cast<float>();
  const float mid_y = 0.5f * (car_min.y() + car_max.y()) - 0.5f * panel.y();
  const float mid_x = 0.5f * (car_min.x() + car_max.x()) - 0.5f * panel.x();
  Eigen::Vector2f at;
  if (car_max.x() + gap + panel.x() <= vp.x()) {
    at = {car_max.x() + gap, mid_y};
  } else if (car_min.x() - gap - panel.x() >= 0.0f) {
    at = {car_min.x() - gap - panel.x(), mid_y};
  } else if (car_max.y() + gap + panel.y() <= vp.y()) {
    at = {mid_x, car_max.y() + gap};
  } else {
    at = {mid_x, car_min.y() - gap - panel.y()};
  }
  at.x() = std::clamp(at.x(), 0.0f, std::max(0.0f, vp.x() - panel.x()));
  at.y() = std::clamp(at.y(), 0.0f, std::max(0.0f, vp.y() - panel.y()));
  return at;
}

Eigen::Vector2f endPanelSize(Canvas& canvas, const EndPanel& panel) {
  const Metrics m = metrics(canvas);
  const Eigen::Vector2f title = canvas.textSize(panel.title, m.big);
  const float table = tableWidth(canvas, tableRows(panel), m.small);
  const float hint = panel.hint.empty() ? 0.0f : canvas.textSize(panel.hint, m.small).x();
  const float w = std::max({title.x(), table, hint}) + 2.0f * m.pad;
  const float row = 1.3f * static_cast<float>(m.small);
  const float h = m.pad + title.y() + 0.5f * m.pad + row * static_cast<float>(panel.rows.size()) +
                  (panel.hint.empty() ? 0.0f : 0.5f * m.pad + row) + m.pad;
  return {w, h};
}

void drawEndPanel(Canvas& canvas, const Camera& camera, const Obb2& car, const EndPanel& panel) {
  const Metrics m = metrics(canvas);
  const Eigen::Vector2f size = endPanelSize(canvas, panel);
  Eigen::Vector2f lo{1e30f, 1e30f};
  Eigen::Vector2f hi{-1e30f, -1e30f};
  for (const Eigen::Vector2f& p : projectObb(camera, car)) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2f tl = placeBeside(canvas.size(), lo, hi, size, 24.0f * m.scale);
  fillRect(canvas, tl, size, panel.background);
  const Eigen::Vector2f title = canvas.textSize(panel.title, m.big);
  canvas.text({tl.x() + 0.5f * (size.x() - title.x()), tl.y() + m.pad}, panel.title, m.big,
              panel.title_color);
  float y = tl.y() + m.pad + title.y() + 0.5f * m.pad;
  y += drawTable(canvas, {tl.x() + m.pad, y}, size.x() - 2.0f * m.pad, tableRows(panel), m.small);
  if (!panel.hint.empty()) {
    const Eigen::Vector2f hs = canvas.textSize(panel.hint, m.small);
    canvas.text({tl.x() + 0.5f * (size.x() - hs.x()), y + 0.5f * m.pad}, panel.hint, m.small, kDim);
  }
}

}  // namespace cardemo
