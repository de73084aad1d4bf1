#pragma once
/// End-of-run panels (PARKED, TIME UP, GAME OVER) placed beside the car, never over it.

#include <string>
#include <utility>
#include <vector>

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"

namespace cardemo {

/// What an end panel says.
struct EndPanel {
  std::string title;                                      ///< e.g. "PARKED".
  Rgba title_color{255, 255, 255, 255};                   ///< Colour of the title.
  Rgba background{12, 14, 18, 215};                       ///< Panel fill.
  std::vector<std::pair<std::string, std::string>> rows;  ///< Label, value (run summary).
  std::string hint;                                       ///< Last line, e.g. the keys.
};

/// Top-left corner for a panel of `panel` pixels beside the screen rectangle [car_min, car_max]:
/// to its right when it fits, else to its left, else below, else above, `gap` pixels away, then
/// clamped into the viewport (a panel larger than the free space may then touch the car).
[[nodiscard]] Eigen::Vector2f placeBeside(const Eigen::Vector2i& viewport,
                                          const Eigen::Vector2f& car_min,
                                          const Eigen::Vector2f& car_max,
                                          const Eigen::Vector2f& panel, float gap);

/// Size in pixels drawEndPanel() needs for `panel` at the HUD scale of the canvas.
[[nodiscard]] Eigen::Vector2f endPanelSize(Canvas& canvas, const EndPanel& panel);

/// Draws `panel` beside the car box `car` as the camera shows it.
void drawEndPanel(Canvas& canvas, const Camera& camera, const Obb2& car, const EndPanel& panel);

}  // namespace cardemo
