#include "render/goal_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "geometry/angle.hpp"
#include "render/end_panel.hpp"
#include "render/gate_marks.hpp"
#include "render/hud.hpp"
#include "render/hud_colors.hpp"
#include "render/panel_place.hpp"
#include "render/shapes.hpp"
#include "sim/parking_readout.hpp"

namespace cardemo {
namespace {

constexpr Rgba kTarget{255, 214, 70, 255};
constexpr Rgba kTargetReady{90, 230, 120, 255};
constexpr Rgba kHoldTrough{55, 58, 64, 255};
constexpr Rgba kWarning{255, 110, 95, 255};
constexpr Rgba kNextBay{255, 214, 70, 90};  // kTarget, faint
using hud_colors::kDim;
using hud_colors::kPanel;
using hud_colors::kText;

Obb2 bayBox(const Goal& goal) {
  return Obb2::fromDegrees(goal.bay.center, goal.bay.heading_deg, goal.bay.length, goal.bay.width);
}

std::string scoreText(const ParkingScore& s) {
  return secondsText(s.seconds) + "  " + starsText(s.stars);
}

int roundPx(float size) {
  return static_cast<int>(std::lround(size));
}

// The timer panel's sizes at a viewport: rows of fixed height, so that its tallest form is known
// without a canvas (hudInsets keeps the scene under it).
struct TimerMetrics {
  float top, pad;
  int big, small, readout;
  float big_row, small_row, extra_row;
};

TimerMetrics timerMetrics(const Eigen::Vector2i& viewport) {
  const float s = hudScale(viewport);
  TimerMetrics m{};
  m.top = 12.0f * s;
  m.pad = 10.0f * s;
  m.big = roundPx(26.0f * s);
  m.small = roundPx(14.0f * s);
  m.readout = roundPx(15.0f * s);
  // A line of text is about 1.17 em high (SDL_ttf, DejaVu Sans).
  m.big_row = 1.2f * static_cast<float>(m.big);
  m.small_row = 1.3f * static_cast<float>(m.small);
  m.extra_row = 0.3f * m.pad + 1.2f * static_cast<float>(m.readout);
  return m;
}

std::string joined(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

// The timer panel at the top centre: the level clock (a bay chain's time left), the detail line,
// and near the bay the readout of what is still off or, while the checks hold, a bar filling over
// the hold time.
void drawTimer(Canvas& canvas, const GoalView& view) {
  const ParkingChallenge& challenge = *view.challenge;
  const Eigen::Vector2i vp = canvas.size();
  const TimerMetrics m = timerMetrics(vp);
  const BayChain* chain = view.chain;
  const std::string time = chain != nullptr ? secondsText(chain->secondsLeft()) + " left"
                                            : secondsText(challenge.seconds());
  const std::string detail = chain != nullptr ? chainDetail(view) : timerDetail(challenge);
  // The chain's challenge never sees the chain end: nothing is off once it has.
  const bool running = !challenge.over() && (chain == nullptr || !chain->over());
  // A fresh miss says so in red where the bay readout goes; it matters more.
  const std::optional<std::string> warning = freshGateWarning(challenge);
  const std::string readout = !running  ? std::string()
                              : warning ? *warning
                                        : joined(bayReadout(challenge), "   ");
  const bool holding =
      running && challenge.holdStart().has_value() && challenge.holdSeconds() > 0.0;
  const bool extra = !readout.empty() || holding;
  const float ts = canvas.textSize(time, m.big).x();
  const float ds = canvas.textSize(detail, m.small).x();
  const float rs = readout.empty() ? 0.0f : canvas.textSize(readout, m.readout).x();
  const float bar_min = holding ? 160.0f * hudScale(vp) : 0.0f;
  const float w = std::max({ts, ds, rs, bar_min}) + 2.0f * m.pad;
  const float h =
      m.big_row + 0.2f * m.pad + m.small_row + (extra ? m.extra_row : 0.0f) + 2.0f * m.pad;
  const Eigen::Vector2f tl{0.5f * (static_cast<float>(vp.x()) - w), m.top};
  fillRect(canvas, tl, {w, h}, kPanel);
  float y = tl.y() + m.pad;
  canvas.text({tl.x() + 0.5f * (w - ts), y}, time, m.big, kText);
  y += m.big_row + 0.2f * m.pad;
  canvas.text({tl.x() + 0.5f * (w - ds), y}, detail, m.small, kDim);
  y += m.small_row + 0.3f * m.pad;
  if (!readout.empty()) {
    canvas.text({tl.x() + 0.5f * (w - rs), y}, readout, m.readout, warning ? kWarning : kTarget);
  } else if (holding) {
    const float bar_h = 0.6f * static_cast<float>(m.readout);
    const Eigen::Vector2f at{tl.x() + m.pad,
                             y + 0.5f * (1.2f * static_cast<float>(m.readout) - bar_h)};
    const float full = w - 2.0f * m.pad;
    const double fraction = std::clamp(challenge.heldSeconds() / challenge.holdSeconds(), 0.0, 1.0);
    fillRect(canvas, at, {full, bar_h}, kHoldTrough);
    if (fraction > 0.0) {
      fillRect(canvas, at, {static_cast<float>(full * fraction), bar_h}, kTargetReady);
    }
  }
}

// Seconds the task is still shown for: the first kTaskSeconds of play and, after that, until the
// car first moves (the level's or the chain's clock starts), then half a second more to fade.
double taskSecondsLeft(const World& world, const GoalView& view) {
  const double hz = world.settings().hz;
  const double now = static_cast<double>(world.frame()) / hz;
  // The chain's clock, not its current bay's: a bay parked without moving on is no new start.
  const std::optional<std::int64_t> start =
      view.chain != nullptr ? view.chain->clockStart() : view.challenge->clockStart();
  if (!start) return std::max(kTaskSeconds - now, 0.5);
  return std::max(kTaskSeconds, static_cast<double>(*start) / hz + 0.5) - now;
}

// The title and task at the start of an attempt (taskSecondsLeft), centred across the screen at
// the top of `area`, or where placeClear() finds room in it clear of `avoid` (the car and the
// bay); fades out over its last half second. Returns its box when drawn.
std::optional<ScreenBox> drawTaskPanel(Canvas& canvas, const World& world, const GoalView& view,
                                       const ScreenBox& area, std::span<const ScreenBox> avoid) {
  const std::optional<GoalTask> level = goalTask(world, view);
  if (!level) return std::nullopt;
  const double left = taskSecondsLeft(world, view);
  if (left <= 0.0) return std::nullopt;
  const float fade = static_cast<float>(std::min(1.0, left / 0.5));
  const auto faded = [fade](Rgba c) {
    c.a = static_cast<std::uint8_t>(std::lround(static_cast<float>(c.a) * fade));
    return c;
  };
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const float gap = 10.0f * s;
  const std::string& heading = level->title;
  // The task is one line: in a narrow window its text is smaller from the start.
  const float room = static_cast<float>(vp.x()) - 2.0f * (gap + 12.0f * s);
  const float natural = canvas.textSize(level->task, roundPx(22.0f * s)).x();
  const float fit = natural > room && natural > 0.0f ? room / natural : 1.0f;
  struct Layout {
    float pad;
    int head, text;
    Eigen::Vector2f hs, ts, size;
  };
  const auto layout = [&](float scale) {
    Layout l{};
    l.pad = 12.0f * s * scale;
    l.head = std::max(6, roundPx(15.0f * s * scale));
    l.text = std::max(6, roundPx(22.0f * s * scale * fit));
    l.hs = canvas.textSize(heading, l.head);
    l.ts = canvas.textSize(level->task, l.text);
    l.size = {std::max(l.hs.x(), l.ts.x()) + 2.0f * l.pad, l.hs.y() + l.ts.y() + 2.4f * l.pad};
    return l;
  };
  const Eigen::Vector2f first = layout(1.0f).size;
  const Eigen::Vector2f preferred{0.5f * (static_cast<float>(vp.x()) - first.x()),
                                  area.min().y() + gap};
  const PanelSpot spot = placeClear(
      area, avoid, gap, [&](float scale) { return layout(scale).size; }, preferred);
  const Layout l = layout(spot.scale);
  const Eigen::Vector2f at = spot.top_left;
  fillRect(canvas, at, l.size, faded({12, 14, 18, 225}));
  canvas.text(at + Eigen::Vector2f{l.pad, l.pad}, heading, l.head, faded(kTarget));
  canvas.text({at.x() + l.pad, at.y() + l.pad + l.hs.y() + 0.4f * l.pad}, level->task, l.text,
              faded(kText));
  return ScreenBox(at, at + l.size);
}

// A filled arrow painted in the bay, pointing along `dir` from its centre towards one end.
void bayArrow(Canvas& canvas, const Camera& camera, const Goal& goal, const Eigen::Vector2d& dir,
              const Rgba& color) {
  const ParkingBay& bay = goal.bay;
  const Eigen::Vector2d side{-dir.y(), dir.x()};
  const auto at = [&](double along, double across) {
    return camera.toScreen(bay.center + dir * (along * bay.length) + side * (across * bay.width));
  };
  // Clear of the "P" painted at the centre; the head stops short of the bay's end.
  const std::array<Eigen::Vector2f, 4> shaft{at(0.13, -0.05), at(0.3, -0.05), at(0.3, 0.05),
                                             at(0.13, 0.05)};
  const std::array<Eigen::Vector2f, 3> head{at(0.43, 0.0), at(0.28, 0.22), at(0.28, -0.22)};
  canvas.fillConvex(shaft, color);
  canvas.fillConvex(head, color);
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
  if (const GateCourse& gates = challenge.gates(); gates.size() > 0) {
    add(gates.done()
            ? std::string("gates done")
            : "gate " + std::to_string(gates.passed() + 1) + "/" + std::to_string(gates.size()));
  }
  if (challenge.bays().size() > 1) {
    add("bay " + std::to_string(challenge.currentBay() + 1) + "/" +
        std::to_string(challenge.bays().size()));
  }
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

std::string chainTaskText(const BayChainSettings& settings) {
  char task[96];
  std::snprintf(task, sizeof task,
                "Park in the highlighted bay, then the next: as many as you can in %g s",
                settings.time_limit);
  return task;
}

std::optional<GoalTask> goalTask(const World& world, const GoalView& view) {
  if (view.chain != nullptr) return GoalTask{"Free drive", chainTaskText(view.chain->settings())};
  const std::optional<LevelInfo>& level = world.scene().level;
  if (!level || level->task.empty()) return std::nullopt;
  return GoalTask{"Level " + std::to_string(level->order) + ": " + level->title, level->task};
}

std::string chainScoreText(const ChainScore& score) {
  return std::to_string(score.count) + (score.count == 1 ? " bay in " : " bays in ") +
         secondsText(score.seconds);
}

std::string chainDetail(const GoalView& view) {
  const BayChain& chain = *view.chain;
  const std::string parked = std::to_string(chain.count()) + " parked";
  if (chain.timedOut()) return "time up   " + parked;
  if (chain.wrecked()) return "wrecked   " + parked;
  std::string detail = parked;
  detail += view.chain_best ? "   best " + std::to_string(view.chain_best->count) : "";
  const ParkingChallenge& c = *view.challenge;
  char text[64];
  if (c.holdStart()) {
    std::snprintf(text, sizeof text, "   hold %.1f / %.1f s", c.heldSeconds(), c.holdSeconds());
  } else {
    std::snprintf(text, sizeof text, "   bay %.1f m", c.lastCheck().distance);
  }
  return detail + text;
}

std::vector<std::pair<std::string, std::string>> chainSummaryRows(const World& world,
                                                                  const GoalView& view) {
  const BayChain& chain = *view.chain;
  std::vector<std::pair<std::string, std::string>> rows;
  rows.emplace_back("Bays parked", std::to_string(chain.count()));
  if (chain.timedOut()) {
    rows.emplace_back("Ended", "time limit " + secondsText(chain.settings().time_limit));
  } else {
    rows.emplace_back("Ended", kWreckedText);
  }
  rows.emplace_back("Damage", std::to_string(world.scene().player.health - world.health()));
  if (view.new_best) {
    rows.emplace_back("Best", "new best!");
  } else if (view.chain_best) {
    rows.emplace_back("Best", chainScoreText(*view.chain_best));
  } else {
    rows.emplace_back("Best", "none yet");
  }
  return rows;
}

std::string starsText(int stars) {
  std::string out;
  for (int i = 0; i < kMaxStars; ++i) out += i < stars ? kStarEarned : kStarMissed;
  return out;
}

std::string secondsText(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  return buf;
}

std::vector<std::string> stillOff(const ParkingChallenge& challenge) {
  std::vector<std::string> reasons = notParkedReasons(challenge);
  // The panel's title and its Ended row already say how the run ended.
  std::erase_if(reasons, [](const std::string& r) { return r == "time up" || r == "wrecked"; });
  return reasons;
}

std::vector<std::pair<std::string, std::string>> runSummaryRows(const World& world,
                                                                const GoalView& view) {
  std::vector<std::pair<std::string, std::string>> rows;
  const ParkingChallenge& c = *view.challenge;
  const std::optional<ParkingScore> score = c.score();
  rows.emplace_back("Time", secondsText(score ? score->seconds : c.seconds()));
  if (score) {
    for (const StarReason& star : starReasons(c.goal(), *score)) {
      rows.emplace_back(std::string(star.earned ? kStarEarned : kStarMissed) + " " + star.text, "");
    }
  } else {
    if (c.timedOut()) {
      rows.emplace_back("Ended", "time limit " + secondsText(c.goal().time_limit.value_or(0.0)));
    } else if (c.wrecked() || world.gameOver()) {
      rows.emplace_back("Ended", kWreckedText);
    }
    const std::vector<std::string> off = stillOff(c);
    if (!off.empty()) rows.emplace_back("Still off", joined(off, ", "));
    rows.emplace_back("Damage", std::to_string(world.scene().player.health - world.health()));
  }
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
  const Goal& goal = c.goal();
  const Rgba color = c.lastCheck().position_ok && c.lastCheck().heading_ok ? kTargetReady : kTarget;
  const std::array<Eigen::Vector2f, 4> bay = projectObb(camera, bayBox(goal));
  outline(canvas, bay, std::max(2.0f, 2.5f * hudScale(canvas.size())), color);
  // The heading the car should end with; both ways when either direction counts.
  const Eigen::Vector2d dir = unitFromDegrees(goal.bay.heading_deg);
  bayArrow(canvas, camera, goal, dir, color);
  if (goal.either_direction) bayArrow(canvas, camera, goal, -dir, color);
  // The chain's next bay, faint: where to head once this one is parked. Only the next: its order
  // is fixed, and the outlines of every free bay would clutter the lot.
  if (view.chain != nullptr && !view.chain->over()) {
    if (const std::optional<std::size_t> next = view.chain->next()) {
      const ParkingBay& bay = view.chain->bays()[*next].bay;
      const Obb2 box = Obb2::fromDegrees(bay.center, bay.heading_deg, bay.length, bay.width);
      outline(canvas, projectObb(camera, box), std::max(1.0f, 1.5f * hudScale(canvas.size())),
              kNextBay);
    }
  }
}

std::vector<ScreenBox> keepClearBoxes(const Camera& camera, const Obb2& player_box,
                                      const GoalView* view) {
  std::vector<ScreenBox> boxes;
  const auto add = [&](const Obb2& box) {
    const auto [lo, hi] = screenRect(camera, box);
    boxes.emplace_back(lo, hi);
  };
  add(player_box);
  if (view != nullptr && view->challenge != nullptr) add(bayBox(view->challenge->goal()));
  return boxes;
}

std::optional<ScreenBox> drawGoalOverlay(Canvas& canvas, const World& world, const Camera& camera,
                                         const Obb2& player_box, const GoalView& view,
                                         const ScreenBox& area, bool show_task) {
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
    const int h = roundPx(15.0f * s);
    const Eigen::Vector2f ts = canvas.textSize(text, h);
    const Eigen::Vector2f label = *at - 30.0f * s * dir - 0.5f * ts - 14.0f * s * dir;
    fillRect(canvas, label - Eigen::Vector2f{4.0f, 2.0f}, ts + Eigen::Vector2f{8.0f, 4.0f}, kPanel);
    canvas.text(label, text, h, kTarget);
  }
  drawTimer(canvas, view);
  std::optional<ScreenBox> task;
  const bool chain_over = view.chain != nullptr && view.chain->over();
  if (show_task && !c.over() && !chain_over) {
    const std::vector<ScreenBox> avoid = keepClearBoxes(camera, player_box, &view);
    task =
        drawTaskPanel(canvas, world, view, area.isEmpty() ? panelArea(canvas.size()) : area, avoid);
  }
  const std::string keys = view.keys.empty() ? std::string("Enter restart    Esc quit") : view.keys;
  if (c.parkedFrame()) {
    drawEndPanel(canvas, camera, player_box,
                 {"PARKED", kTargetReady, {10, 40, 20, 215}, runSummaryRows(world, view), keys});
  } else if (c.timedOut()) {
    drawEndPanel(
        canvas, camera, player_box,
        {"TIME UP", {255, 90, 80, 255}, {60, 10, 12, 215}, runSummaryRows(world, view), keys});
  } else if (view.chain != nullptr && view.chain->timedOut()) {
    // Wrecked, the GAME OVER panel says it (DrawOptions::game_over_rows: chainSummaryRows).
    drawEndPanel(
        canvas, camera, player_box,
        {"TIME UP", {255, 214, 70, 255}, {40, 34, 10, 215}, chainSummaryRows(world, view), keys});
  }
  return task;
}

float timerPanelBottom(const Eigen::Vector2i& viewport) {
  const TimerMetrics m = timerMetrics(viewport);
  return m.top + m.pad + m.big_row + 0.2f * m.pad + m.small_row + m.extra_row + m.pad;
}

}  // namespace cardemo
