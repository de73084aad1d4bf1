#include "render/goal_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "render/end_panel.hpp"
#include "render/hud.hpp"
#include "render/hud_colors.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

constexpr Rgba kTarget{255, 214, 70, 255};
constexpr Rgba kTargetReady{90, 230, 120, 255};
using hud_colors::kDim;
using hud_colors::kPanel;
using hud_colors::kText;

Obb2 bayBox(const Goal& goal) {
  return Obb2::fromDegrees(goal.bay.center, goal.bay.heading_deg, goal.bay.length, goal.bay.width);
}

std::string scoreText(const ParkingScore& s) {
  return secondsText(s.seconds) + "  " + starsText(s.stars);
}

// Returns the bottom of the timer panel, pixels.
float drawTimer(Canvas& canvas, const ParkingChallenge& challenge) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const int big = static_cast<int>(std::lround(26.0f * s));
  const int small = static_cast<int>(std::lround(14.0f * s));
  const float pad = 10.0f * s;
  const std::string time = secondsText(challenge.seconds());
  const std::string detail = timerDetail(challenge);
  const Eigen::Vector2f ts = canvas.textSize(time, big);
  const Eigen::Vector2f ds = canvas.textSize(detail, small);
  const float w = std::max(ts.x(), ds.x()) + 2.0f * pad;
  const float h = ts.y() + ds.y() + 2.2f * pad;
  const Eigen::Vector2f tl{0.5f * (static_cast<float>(vp.x()) - w), 12.0f * s};
  fillRect(canvas, tl, {w, h}, kPanel);
  canvas.text({tl.x() + 0.5f * (w - ts.x()), tl.y() + pad}, time, big, kText);
  canvas.text({tl.x() + 0.5f * (w - ds.x()), tl.y() + pad * 1.2f + ts.y()}, detail, small, kDim);
  return tl.y() + h;
}

// Area of the rectangle [at, at + size] that the rectangles `avoid` cover (overlaps summed).
float coveredArea(const Eigen::Vector2f& at, const Eigen::Vector2f& size,
                  const std::vector<std::pair<Eigen::Vector2f, Eigen::Vector2f>>& avoid) {
  float area = 0.0f;
  for (const auto& [lo, hi] : avoid) {
    const Eigen::Vector2f a = lo.cwiseMax(at);
    const Eigen::Vector2f b = hi.cwiseMin(at + size);
    if (b.x() > a.x() && b.y() > a.y()) area += (b.x() - a.x()) * (b.y() - a.y());
  }
  return area;
}

// The level's title and task for the first kTaskSeconds of an attempt, centred across the screen
// under the timer (and the HUD panel), or above the status line when the car or the bay is there;
// fades out over its last half second.
void drawTaskPanel(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
                   const Goal& goal, float timer_bottom, const Eigen::Vector2f& hud_corner) {
  const std::optional<LevelInfo>& level = world.scene().level;
  if (!level || level->task.empty()) return;
  const double left = kTaskSeconds - static_cast<double>(world.frame()) / world.settings().hz;
  if (left <= 0.0) return;
  const float fade = static_cast<float>(std::min(1.0, left / 0.5));
  const auto faded = [fade](Rgba c) {
    c.a = static_cast<std::uint8_t>(std::lround(static_cast<float>(c.a) * fade));
    return c;
  };
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const float pad = 12.0f * s;
  const float gap = 10.0f * s;
  const int head = static_cast<int>(std::lround(15.0f * s));
  const std::string heading = "Level " + std::to_string(level->order) + ": " + level->title;
  // Shrunk to fit a narrow window: the task is one line.
  int text = static_cast<int>(std::lround(22.0f * s));
  const float room = static_cast<float>(vp.x()) - 2.0f * (gap + pad);
  const float natural = canvas.textSize(level->task, text).x();
  if (natural > room && natural > 0.0f) {
    text = std::max(8, static_cast<int>(static_cast<float>(text) * room / natural));
  }
  const Eigen::Vector2f hs = canvas.textSize(heading, head);
  const Eigen::Vector2f ts = canvas.textSize(level->task, text);
  const Eigen::Vector2f size{std::max(hs.x(), ts.x()) + 2.0f * pad,
                             hs.y() + ts.y() + 0.4f * pad + 2.0f * pad};
  const float x = 0.5f * (static_cast<float>(vp.x()) - size.x());
  // Above the status line at the bottom left.
  const float status_top = statusLineTop(vp);
  const std::vector<std::pair<Eigen::Vector2f, Eigen::Vector2f>> avoid{
      screenRect(camera, player_box), screenRect(camera, bayBox(goal))};
  // A wide panel reaches under the HUD panel at the top left: it goes below both.
  Eigen::Vector2f at{
      x, (x < hud_corner.x() ? std::max(timer_bottom, hud_corner.y()) : timer_bottom) + gap};
  const Eigen::Vector2f low{x, status_top - gap - size.y()};
  if (coveredArea(at, size, avoid) > 0.0f &&
      coveredArea(low, size, avoid) < coveredArea(at, size, avoid)) {
    at = low;
  }
  fillRect(canvas, at, size, faded({12, 14, 18, 225}));
  canvas.text(at + Eigen::Vector2f{pad, pad}, heading, head, faded(kTarget));
  canvas.text({at.x() + pad, at.y() + pad + hs.y() + 0.4f * pad}, level->task, text, faded(kText));
}

}  // namespace

std::string timerDetail(const ParkingChallenge& challenge) {
  const Goal& goal = challenge.goal();
  std::string detail;
  const auto add = [&detail](const std::string& part) {
    detail += (detail.empty() ? "" : "   ") + part;
  };
  if (challenge.parkedFrame()) {
    add("parked");
    if (goal.par_time) add("par " + secondsText(*goal.par_time));
    return detail;
  }
  if (challenge.timedOut()) return "time up";
  if (challenge.wrecked()) return "wrecked";
  if (goal.par_time) add("par " + secondsText(*goal.par_time));
  if (goal.time_limit) {
    add("left " + secondsText(std::max(0.0, *goal.time_limit - challenge.seconds())));
  }
  char text[64];
  if (challenge.holdStart()) {
    std::snprintf(text, sizeof text, "hold %.1f / %.1f s", challenge.heldSeconds(),
                  challenge.holdSeconds());
  } else {
    std::snprintf(text, sizeof text, "bay %.1f m", challenge.lastCheck().distance);
  }
  add(text);
  return detail;
}

std::string starsText(int stars) {
  std::string out;
  for (int i = 0; i < kMaxStars; ++i) out += i < stars ? "\xE2\x98\x85" : "\xE2\x98\x86";
  return out;
}

std::string secondsText(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  return buf;
}

std::vector<std::pair<std::string, std::string>> runSummaryRows(const World& world,
                                                                const GoalView& view) {
  std::vector<std::pair<std::string, std::string>> rows;
  const ParkingChallenge& c = *view.challenge;
  const std::optional<ParkingScore> score = c.score();
  rows.emplace_back("Time", secondsText(score ? score->seconds : c.seconds()));
  const int damage = world.scene().player.health - world.health();
  rows.emplace_back("Damage", std::to_string(score ? score->damage : damage));
  rows.emplace_back("Stars", starsText(score ? score->stars : 0));
  if (view.new_best) {
    rows.emplace_back("Best", "new best!");
  } else if (view.best) {
    rows.emplace_back("Best", scoreText(*view.best));
  } else {
    rows.emplace_back("Best", "none yet");
  }
  return rows;
}

std::optional<Eigen::Vector2f> edgeAnchor(const Eigen::Vector2i& viewport,
                                          const Eigen::Vector2f& target, float margin) {
  const Eigen::Vector2f half = 0.5f * viewport.cast<float>();
  const Eigen::Vector2f d = target - half;
  const float hx = std::max(1.0f, half.x() - margin);
  const float hy = std::max(1.0f, half.y() - margin);
  const float t = std::max(std::abs(d.x()) / hx, std::abs(d.y()) / hy);
  if (t <= 1.0f) return std::nullopt;
  return half + d / t;
}

void drawGoalBay(Canvas& canvas, const Camera& camera, const GoalView& view) {
  const ParkingChallenge& c = *view.challenge;
  const Rgba color = c.lastCheck().position_ok && c.lastCheck().heading_ok ? kTargetReady : kTarget;
  const std::array<Eigen::Vector2f, 4> bay = projectObb(camera, bayBox(c.goal()));
  outline(canvas, bay, std::max(2.0f, 2.5f * hudScale(canvas.size())), color);
}

void drawGoalOverlay(Canvas& canvas, const World& world, const Camera& camera,
                     const Obb2& player_box, const GoalView& view,
                     const Eigen::Vector2f& hud_corner) {
  const ParkingChallenge& c = *view.challenge;
  const Goal& goal = c.goal();
  const float s = hudScale(canvas.size());
  const Eigen::Vector2f target = camera.toScreen(goal.bay.center);
  const float margin = 48.0f * s;
  if (const std::optional<Eigen::Vector2f> at = edgeAnchor(canvas.size(), target, margin)) {
    const Eigen::Vector2f dir = (target - *at).normalized();
    arrow(canvas, *at - 30.0f * s * dir, *at + 6.0f * s * dir, 5.0f * s, 16.0f * s, kTarget);
    char text[32];
    std::snprintf(text, sizeof text, "%.0f m", c.lastCheck().distance);
    const int h = static_cast<int>(std::lround(15.0f * s));
    const Eigen::Vector2f ts = canvas.textSize(text, h);
    const Eigen::Vector2f label = *at - 30.0f * s * dir - 0.5f * ts - 14.0f * s * dir;
    fillRect(canvas, label - Eigen::Vector2f{4.0f, 2.0f}, ts + Eigen::Vector2f{8.0f, 4.0f}, kPanel);
    canvas.text(label, text, h, kTarget);
  }
  const float timer_bottom = drawTimer(canvas, c);
  if (!c.over()) drawTaskPanel(canvas, world, camera, player_box, goal, timer_bottom, hud_corner);

  if (c.parkedFrame()) {
    drawEndPanel(canvas, camera, player_box,
                 {"PARKED",
                  kTargetReady,
                  {10, 40, 20, 215},
                  runSummaryRows(world, view),
                  view.keys.empty() ? std::string("Enter restart    Esc quit") : view.keys});
  } else if (c.timedOut()) {
    drawEndPanel(canvas, camera, player_box,
                 {"TIME UP",
                  {255, 90, 80, 255},
                  {60, 10, 12, 215},
                  runSummaryRows(world, view),
                  view.keys.empty() ? std::string("Enter restart    Esc quit") : view.keys});
  }
}

}  // namespace cardemo
