#pragma once
/// The parking challenge on screen: the target bay (on the ground), an arrow to it when it is off
/// screen, the timer, and the PARKED / TIME UP panel beside the car.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Seconds of play at the start of an attempt during which a level's task is shown.
inline constexpr double kTaskSeconds = 4.0;

/// What the overlay shows besides the world.
struct GoalView {
  const ParkingChallenge* challenge = nullptr;  ///< The run's challenge (required).
  std::optional<ParkingScore> best;             ///< Best score before this run, if any.
  bool new_best = false;                        ///< This run's score was just saved as the best.
  std::string
      keys;  ///< Keys line of the PARKED / TIME UP panel; empty: "Enter restart    Esc quit".
};

/// Three stars, filled for the ones earned: "★★☆".
[[nodiscard]] std::string starsText(int stars);

/// "12.3 s".
[[nodiscard]] std::string secondsText(double seconds);

/// The run summary rows of an end panel: time, damage, stars and best.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> runSummaryRows(const World& world,
                                                                              const GoalView& view);

/// Where the arrow to an off-screen point sits: the point pulled back along the ray from the
/// screen centre so that it is `margin` pixels inside the viewport. Returns nullopt when the
/// point is already at least `margin` inside.
[[nodiscard]] std::optional<Eigen::Vector2f> edgeAnchor(const Eigen::Vector2i& viewport,
                                                        const Eigen::Vector2f& target,
                                                        float margin);

/// The line under the timer: par, time left and distance to the bay while driving; the hold
/// while the car is in the bay; then what ended the run.
[[nodiscard]] std::string timerDetail(const ParkingChallenge& challenge);

/// The target bay's outline, yellow, green once the car's position and heading are within the
/// tolerances: paint on the ground, which drawWorldLayer draws under the cars.
void drawGoalBay(Canvas& canvas, const Camera& camera, const GoalView& view);

/// Draws the off-screen arrow with the distance to the bay, the timer, the level's task
/// (`level.task`, for the first kTaskSeconds of play, clear of the car, the bay and the HUD panel
/// whose bottom-right corner is `hud_corner` when it can be), and the end panel when the car has
/// parked or the time is up.
void drawGoalOverlay(Canvas& canvas, const World& world, const Camera& camera,
                     const Obb2& player_box, const GoalView& view,
                     const Eigen::Vector2f& hud_corner = Eigen::Vector2f::Zero());

}  // namespace cardemo
