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
#include "render/panel_place.hpp"
#include "sim/bay_chain.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Seconds of play at the start of an attempt during which a level's task is shown (and after
/// them until the car first moves).
inline constexpr double kTaskSeconds = 4.0;

/// A star earned and a star missed, as the panels write them.
inline constexpr const char* kStarEarned = "\xE2\x98\x85";
inline constexpr const char* kStarMissed = "\xE2\x98\x86";
/// The end panels' words for a run that ended at health 0.
inline constexpr const char* kWreckedText = "wrecked (health 0)";

/// What the overlay shows besides the world.
struct GoalView {
  const ParkingChallenge* challenge = nullptr;  ///< The run's challenge (required).
  std::optional<ParkingScore> best;             ///< Best score before this run, if any.
  bool new_best = false;  ///< This run's score (or chain) was just saved as the best.
  std::string
      keys;  ///< Keys line of the PARKED / TIME UP panel; empty: "Enter restart    Esc quit".
  /// Free drive's bay chain, whose highlighted bay `challenge` judges; null for a level.
  const BayChain* chain = nullptr;
  std::optional<ChainScore> chain_best;  ///< With `chain`: the best chain before this run, if any.
};

/// The title and the task a goal's panel shows (a level's, or free drive's bay chain), or
/// nullopt when there is none.
struct GoalTask {
  std::string title;  ///< "Level 2: Reverse bay", "Free drive".
  std::string task;   ///< One line: what to do.
};

/// Free drive's task: "Park in the highlighted bay, then the next: as many as you can in 180 s".
[[nodiscard]] std::string chainTaskText(const BayChainSettings& settings = {});

/// The task of `view` in `world` (the level's `level.task`, or the bay chain's).
[[nodiscard]] std::optional<GoalTask> goalTask(const World& world, const GoalView& view);

/// "4 bays in 170.2 s" ("1 bay in 12.3 s"): a chain's count and when its last bay was parked.
[[nodiscard]] std::string chainScoreText(const ChainScore& score);

/// The line under the bay chain's clock: the count, the best and the distance to the highlighted
/// bay (or its hold) while it runs; how it ended, and the count, once it is over.
[[nodiscard]] std::string chainDetail(const GoalView& view);

/// The bay chain's end panel rows (TIME UP, or GAME OVER when wrecked): the bays parked, what
/// ended it, the damage, and the best ("new best!" when this chain was saved as the best).
[[nodiscard]] std::vector<std::pair<std::string, std::string>> chainSummaryRows(
    const World& world, const GoalView& view);

/// Three stars, filled for the ones earned: "★★☆".
[[nodiscard]] std::string starsText(int stars);

/// "12.3 s".
[[nodiscard]] std::string secondsText(double seconds);

/// What was still off when a run ended unparked (notParkedReasons without "time up" and
/// "wrecked", which the panel's title and Ended row say): the readout's words, the distance to
/// the bay, or the hold.
[[nodiscard]] std::vector<std::string> stillOff(const ParkingChallenge& challenge);

/// The run summary rows of an end panel. PARKED: the time, then each star earned (★) or missed
/// (☆) and why ("★ parked", "☆ 6 damage", "☆ over par by 3.2 s"), then the best. TIME UP and a
/// level's GAME OVER: the time, what ended the run (Ended), what was still off, the damage and
/// the best.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> runSummaryRows(const World& world,
                                                                              const GoalView& view);

/// Where the arrow to an off-screen point sits: the point pulled back along the ray from the
/// screen centre so that it is `margin` pixels inside the viewport. Returns nullopt when the
/// point is already at least `margin` inside.
[[nodiscard]] std::optional<Eigen::Vector2f> edgeAnchor(const Eigen::Vector2i& viewport,
                                                        const Eigen::Vector2f& target,
                                                        float margin);

/// The line under the timer: par, the gate and the bay of a chain to take next ("gate 2/3", "bay
/// 1/2"), time left and distance to the bay while driving; the hold while the car is in the bay;
/// then what ended the run.
[[nodiscard]] std::string timerDetail(const ParkingChallenge& challenge);

/// The lowest the timer panel reaches in a viewport (with its readout row), pixels: the HUD's
/// top strip (hudInsets) covers it.
[[nodiscard]] float timerPanelBottom(const Eigen::Vector2i& viewport);

/// The target bay's outline, yellow, green once the car's position and heading are within the
/// tolerances, with an arrow inside pointing the way the car should face (two, one each way, when
/// either direction counts): paint on the ground, which drawWorldLayer draws under the cars. With
/// a bay chain, the bay after it is outlined faintly (no arrow), so that the player can plan how
/// to leave this one; the later bays are not drawn.
void drawGoalBay(Canvas& canvas, const Camera& camera, const GoalView& view);

/// The screen boxes that panels must not cover: the player's car and, with a goal, its bay.
[[nodiscard]] std::vector<ScreenBox> keepClearBoxes(const Camera& camera, const Obb2& player_box,
                                                    const GoalView* view);

/// Draws the off-screen arrow with the distance to the bay, the timer (with the readout of what
/// is still off near the bay, and the hold's bar; for a bay chain the time left, the count and
/// the best), the task (goalTask(): for the first kTaskSeconds of play and until the car first
/// moves, placed in `area` (empty: panelArea()) clear of the car and the bay; not with
/// `show_task` false), and the end panel when the car has parked or the time is up. Returns the
/// task panel's box when it was drawn.
std::optional<ScreenBox> drawGoalOverlay(Canvas& canvas, const World& world, const Camera& camera,
                                         const Obb2& player_box, const GoalView& view,
                                         const ScreenBox& area = {}, bool show_task = true);

}  // namespace cardemo
