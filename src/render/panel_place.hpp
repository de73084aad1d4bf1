#pragma once
/// Where a screen panel (PAUSED, the help, the level's task) goes so that it covers neither the
/// car nor the bay: where it would go, else above, below, left or right of them, shrunk when
/// nothing fits.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace cardemo {

/// A screen rectangle, pixels (y down).
using ScreenBox = Eigen::AlignedBox2f;

/// Where a panel goes and at what size.
struct PanelSpot {
  Eigen::Vector2f top_left = Eigen::Vector2f::Zero();  ///< Pixels.
  float scale = 1.0f;  ///< Factor on the panel's natural size (text and padding); 1: natural.
};

/// The size of a panel drawn at `scale` times its natural size, pixels.
using PanelSizer = std::function<Eigen::Vector2f(float scale)>;

/// Smallest factor placeClear() shrinks a panel by: smaller text would not be read.
inline constexpr float kMinPanelScale = 0.4f;

/// Places a panel inside `area`, clear of every box of `avoid` grown by `gap` (boxes outside the
/// area do not count): at `preferred` (top-left at natural size) when that is inside the area and
/// clear; else centred in the free band above all the boxes, below them, left of them or right of
/// them, the first where it fits at natural size; else in the band where it fits largest, shrunk
/// to fit (to no less than kMinPanelScale, where it may then overlap).
[[nodiscard]] PanelSpot placeClear(const ScreenBox& area, std::span<const ScreenBox> avoid,
                                   float gap, const PanelSizer& size_at,
                                   const std::optional<Eigen::Vector2f>& preferred = std::nullopt);

/// The part of the viewport between the HUD's strips (hudInsets), and below `hud_bottom` (the
/// HUD panel's bottom as drawn: a replay's playback makes it taller): where panels go.
[[nodiscard]] ScreenBox panelArea(const Eigen::Vector2i& viewport, float hud_bottom = 0.0f);

/// Where screen panels may go and what they must not cover.
struct PanelRoom {
  ScreenBox area;                ///< Where panels go; empty: panelArea(viewport).
  std::vector<ScreenBox> avoid;  ///< Boxes not to cover: the car's and the bay's on screen.
};

/// True when the open interiors of `a` and `b` share a point (touching edges do not overlap).
[[nodiscard]] bool boxesOverlap(const ScreenBox& a, const ScreenBox& b);

}  // namespace cardemo
