#include "render/scene_picker_view.hpp"

#include <algorithm>
#include <cmath>

#include "render/hud.hpp"
#include "render/hud_colors.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

constexpr Rgba kBackground{24, 26, 30};
using hud_colors::kDim;
using hud_colors::kText;
constexpr Rgba kSelected{70, 110, 170, 255};
constexpr Rgba kTitle{255, 214, 70, 255};
constexpr Rgba kTask{225, 232, 245, 255};

}  // namespace

void drawScenePicker(Canvas& canvas, const std::vector<PickerRow>& rows, int selected,
                     const std::string& summary) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const int big = static_cast<int>(std::lround(36.0f * s));
  const int text = static_cast<int>(std::lround(20.0f * s));
  const int small = static_cast<int>(std::lround(15.0f * s));
  canvas.clear(kBackground);
  const std::string title = "cardemo: choose a scene";
  const Eigen::Vector2f ts = canvas.textSize(title, big);
  const float cx = 0.5f * static_cast<float>(vp.x());
  float y = 60.0f * s;
  canvas.text({cx - 0.5f * ts.x(), y}, title, big, kTitle);
  y += ts.y() + 30.0f * s;
  if (!summary.empty()) {
    const Eigen::Vector2f ss = canvas.textSize(summary, text);
    canvas.text({cx - 0.5f * ss.x(), y - 18.0f * s}, summary, text, kTask);
    y += ss.y() + 6.0f * s;
  }

  float title_w = 0.0f;
  float detail_w = 0.0f;
  float task_w = 0.0f;
  for (const PickerRow& r : rows) {
    title_w = std::max(title_w, canvas.textSize(r.title, text).x());
    detail_w = std::max(detail_w, canvas.textSize(r.detail, text).x());
    task_w = std::max(task_w, canvas.textSize(r.task, small).x());
  }
  const float pad = 14.0f * s;
  // As wide as the widest task too, so that selecting a row never changes the list's width.
  const float width =
      std::max(title_w + 3.0f * static_cast<float>(text) + detail_w, task_w) + 2.0f * pad;
  const float row_h = 1.8f * static_cast<float>(text);
  const float task_h = 1.6f * static_cast<float>(small);
  const float left = cx - 0.5f * width;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool sel = static_cast<int>(i) == selected;
    const bool task = sel && !rows[i].task.empty();
    if (sel) fillRect(canvas, {left, y}, {width, row_h + (task ? task_h : 0.0f)}, kSelected);
    const float ty = y + 0.5f * (row_h - static_cast<float>(text) * 1.15f);
    canvas.text({left + pad, ty}, rows[i].title, text, kText);
    const float dw = canvas.textSize(rows[i].detail, text).x();
    canvas.text({left + width - pad - dw, ty}, rows[i].detail, text, sel ? kText : kDim);
    y += row_h;
    if (task) {
      canvas.text({left + pad, y - 0.05f * row_h}, rows[i].task, small, kTask);
      y += task_h;
    }
  }
  const std::string keys = "Up / Down or W / S: choose     Enter: play     Esc: quit";
  const Eigen::Vector2f ks = canvas.textSize(keys, small);
  canvas.text({cx - 0.5f * ks.x(), static_cast<float>(vp.y()) - ks.y() - 24.0f * s}, keys, small,
              kDim);
}

}  // namespace cardemo
