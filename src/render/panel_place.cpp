#include "render/panel_place.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "render/hud.hpp"

namespace cardemo {
namespace {

Eigen::Vector2f extent(const ScreenBox& box) {
  return (box.max() - box.min()).cwiseMax(0.0f);
}

bool fitsIn(const Eigen::Vector2f& size, const ScreenBox& band) {
  const Eigen::Vector2f room = extent(band);
  return size.x() <= room.x() && size.y() <= room.y();
}

// Top-left of a panel of `size` centred in `band`, kept inside `area`.
Eigen::Vector2f centredIn(const ScreenBox& band, const Eigen::Vector2f& size,
                          const ScreenBox& area) {
  const Eigen::Vector2f at = 0.5f * (band.min() + band.max() - size);
  return at.cwiseMin(area.max() - size).cwiseMax(area.min());
}

}  // namespace

bool boxesOverlap(const ScreenBox& a, const ScreenBox& b) {
  return a.min().x() < b.max().x() && b.min().x() < a.max().x() && a.min().y() < b.max().y() &&
         b.min().y() < a.max().y();
}

ScreenBox panelArea(const Eigen::Vector2i& viewport, float hud_bottom) {
  const ViewInsets strips = hudInsets(viewport);
  const float gap = 8.0f * hudScale(viewport);
  return {Eigen::Vector2f{0.0f, std::max(strips.top, hud_bottom + gap)},
          Eigen::Vector2f{static_cast<float>(viewport.x()),
                          static_cast<float>(viewport.y()) - strips.bottom}};
}

PanelSpot placeClear(const ScreenBox& area, std::span<const ScreenBox> avoid, float gap,
                     const PanelSizer& size_at, const std::optional<Eigen::Vector2f>& preferred) {
  const Eigen::Vector2f natural = size_at(1.0f);
  // Half a pixel to spare on every side, so that rounding in the sums below cannot make a panel
  // touch what it must clear.
  const Eigen::Vector2f slack = Eigen::Vector2f::Constant(0.5f);
  const ScreenBox room(area.min() + slack, area.max() - slack);
  const Eigen::Vector2f grow = Eigen::Vector2f::Constant(gap) + slack;
  std::vector<ScreenBox> blocked;
  ScreenBox all;  // empty: every box grown, together
  for (const ScreenBox& box : avoid) {
    const ScreenBox grown(box.min() - grow, box.max() + grow);
    if (!boxesOverlap(grown, room)) continue;
    blocked.push_back(grown);
    all.extend(grown);
  }
  const auto clear = [&](const ScreenBox& panel) {
    return room.contains(panel) &&
           std::none_of(blocked.begin(), blocked.end(),
                        [&panel](const ScreenBox& b) { return boxesOverlap(panel, b); });
  };
  if (preferred && clear(ScreenBox(*preferred, *preferred + natural))) return {*preferred, 1.0f};

  std::vector<ScreenBox> bands;
  if (blocked.empty()) {
    bands.push_back(room);
  } else {
    const Eigen::Vector2f lo = room.min(), hi = room.max();
    bands = {ScreenBox(lo, Eigen::Vector2f{hi.x(), all.min().y()}),
             ScreenBox(Eigen::Vector2f{lo.x(), all.max().y()}, hi),
             ScreenBox(lo, Eigen::Vector2f{all.min().x(), hi.y()}),
             ScreenBox(Eigen::Vector2f{all.max().x(), lo.y()}, hi)};
  }
  for (const ScreenBox& band : bands) {
    if (fitsIn(natural, band)) return {centredIn(band, natural, area), 1.0f};
  }
  // Nothing fits whole: the band that holds the largest copy, shrunk until it fits there.
  float best = -1.0f;
  const ScreenBox* chosen = &bands.front();
  for (const ScreenBox& band : bands) {
    const Eigen::Vector2f room = extent(band);
    const float scale =
        std::min(room.x() / std::max(natural.x(), 1.0f), room.y() / std::max(natural.y(), 1.0f));
    if (scale > best) {
      best = scale;
      chosen = &band;
    }
  }
  // Text sizes round to whole pixels, so the size is measured again at each factor tried.
  float scale = std::clamp(best, kMinPanelScale, 1.0f);
  while (scale > kMinPanelScale && !fitsIn(size_at(scale), *chosen)) {
    scale = std::max(kMinPanelScale, scale * 0.97f);
  }
  return {centredIn(*chosen, size_at(scale), area), scale};
}

}  // namespace cardemo
