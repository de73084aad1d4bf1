#include "render/draw_world.hpp"

#include <cstdint>
#include <optional>
#include <string>

#include "render/debug_overlay.hpp"
#include "render/effects_layer.hpp"
#include "render/goal_overlay.hpp"
#include "render/hud.hpp"
#include "render/panel_place.hpp"
#include "render/world_layer.hpp"

namespace cardemo {

void drawFrame(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
               const DrawOptions& options, const Palette& palette) {
  canvas.clear(world.scene().bounds ? palette.outside : palette.ground);
  drawWorldLayer(canvas, world, camera, player_box, options, palette);
  if (options.debug_overlay) drawDebugOverlay(canvas, world, camera);
  if (options.effects != nullptr) drawDamageNumbers(canvas, camera, *options.effects, palette);
  const Eigen::Vector2f hud = drawHud(canvas, world, options);
  if (options.effects != nullptr) drawHealthPulse(canvas, world, *options.effects);
  // Panels drawn over the world keep clear of the car and the bay (players could not see where
  // they were parking under PAUSED), and below the HUD panel as drawn.
  PanelRoom room{panelArea(canvas.size(), hud.y()),
                 keepClearBoxes(camera, player_box, options.goal)};
  if (options.goal != nullptr) {
    // The help lists the task itself: no second copy under it.
    if (const std::optional<ScreenBox> task = drawGoalOverlay(
            canvas, world, camera, player_box, *options.goal, room.area, !options.help)) {
      room.avoid.push_back(*task);  // and PAUSED keeps clear of the task
    }
  }
  if (world.gameOver())
    drawGameOver(canvas, world, camera, player_box, options.game_over_rows, options.game_over_keys);
  // Last, so that nothing covers them; the help panel carries PAUSED in its title.
  const std::string banner =
      !options.banner.empty() ? options.banner : (options.paused ? "PAUSED" : "");
  if (options.help) {
    // The goal's task (a level's, or the bay chain's); a level drawn without its goal has its own.
    const std::optional<LevelInfo>& level = world.scene().level;
    const std::optional<GoalTask> task =
        options.goal != nullptr ? goalTask(world, *options.goal)
        : level                 ? std::optional<GoalTask>(GoalTask{level->title, level->task})
                                : std::nullopt;
    // The game waits while the help is shown: it may cover the HUD, so its room is the window.
    const Eigen::Vector2f margin = Eigen::Vector2f::Constant(8.0f * hudScale(canvas.size()));
    room.area = ScreenBox(margin, canvas.size().cast<float>() - margin);
    (void)drawHelp(canvas, banner, task ? task->task : std::string(), room);
  } else {
    (void)drawBanner(canvas, banner, room);
  }
}

Rgba parkedColor(const std::string& id, const Palette& palette) {
  // FNV-1a, 32 bits (Fowler, Noll, Vo): stable across runs, platforms and compilers.
  std::uint32_t h = 2166136261u;
  for (const char c : id) {
    h ^= static_cast<std::uint8_t>(c);
    h *= 16777619u;
  }
  return palette.car_colors[h % palette.car_colors.size()];
}

Camera followCamera(const Obb2& player_box, double pixels_per_metre,
                    const Eigen::Vector2i& viewport) {
  Camera camera;
  camera.center = player_box.center;
  camera.pixels_per_metre = pixels_per_metre;
  camera.viewport = viewport;
  return camera;
}

}  // namespace cardemo
