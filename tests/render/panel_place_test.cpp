// Panels that never cover the bay or the car: placeClear on its own, then PAUSED, the help and the
// task banner over every level at its start and at its golden replay's parked pose.

#include "render/panel_place.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"
#include "recording_canvas.hpp"
#include "render/camera_rig.hpp"
#include "render/draw_world.hpp"
#include "render/goal_overlay.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

using test::RecordingCanvas;

const ScreenBox kArea(Eigen::Vector2f(0.0f, 100.0f), Eigen::Vector2f(1280.0f, 680.0f));

// A panel of `size` at natural size that scales linearly.
PanelSizer linear(const Eigen::Vector2f& size) {
  return [size](float scale) { return Eigen::Vector2f(size * scale); };
}

ScreenBox boxAt(const PanelSpot& spot, const PanelSizer& size_at) {
  return {spot.top_left, spot.top_left + size_at(spot.scale)};
}

ScreenBox grown(const ScreenBox& b, float gap) {
  return {b.min() - Eigen::Vector2f::Constant(gap), b.max() + Eigen::Vector2f::Constant(gap)};
}

TEST(PanelPlace, OverlapsIgnoresTouchingEdges) {
  const ScreenBox a(Eigen::Vector2f(0, 0), Eigen::Vector2f(10, 10));
  EXPECT_TRUE(boxesOverlap(a, ScreenBox(Eigen::Vector2f(9, 9), Eigen::Vector2f(20, 20))));
  EXPECT_FALSE(boxesOverlap(a, ScreenBox(Eigen::Vector2f(10, 0), Eigen::Vector2f(20, 10))));
  EXPECT_FALSE(boxesOverlap(a, ScreenBox(Eigen::Vector2f(0, 10), Eigen::Vector2f(10, 20))));
}

TEST(PanelPlace, PreferredSpotWhenItIsClear) {
  const PanelSizer size = linear({300, 80});
  const std::vector<ScreenBox> car{ScreenBox(Eigen::Vector2f(600, 350), Eigen::Vector2f(700, 400))};
  const PanelSpot spot = placeClear(kArea, car, 10.0f, size, Eigen::Vector2f(490, 200));
  EXPECT_EQ(spot.top_left, Eigen::Vector2f(490, 200));
  EXPECT_EQ(spot.scale, 1.0f);
}

// Above the boxes first, then below, then left, then right; each centred in its band.
TEST(PanelPlace, TopThenBottomThenLeftThenRight) {
  const PanelSizer size = linear({300, 80});
  const Eigen::Vector2f preferred(490, 330);  // over the car in every case
  struct Case {
    const char* want;
    ScreenBox car;
  };
  for (const Case& c :
       {Case{"top", ScreenBox(Eigen::Vector2f(600, 300), Eigen::Vector2f(700, 400))},
        Case{"bottom", ScreenBox(Eigen::Vector2f(600, 150), Eigen::Vector2f(700, 400))},
        Case{"left", ScreenBox(Eigen::Vector2f(600, 150), Eigen::Vector2f(700, 620))},
        Case{"right", ScreenBox(Eigen::Vector2f(200, 150), Eigen::Vector2f(700, 620))}}) {
    const std::vector<ScreenBox> avoid{c.car};
    const PanelSpot spot = placeClear(kArea, avoid, 10.0f, size, preferred);
    const ScreenBox panel = boxAt(spot, size);
    EXPECT_EQ(spot.scale, 1.0f) << c.want;
    EXPECT_FALSE(boxesOverlap(panel, grown(c.car, 10.0f))) << c.want;
    EXPECT_TRUE(kArea.contains(panel)) << c.want;
    const std::string side = panel.max().y() <= c.car.min().y()   ? "top"
                             : panel.min().y() >= c.car.max().y() ? "bottom"
                             : panel.max().x() <= c.car.min().x() ? "left"
                                                                  : "right";
    EXPECT_EQ(side, c.want);
  }
}

TEST(PanelPlace, ShrinksWhenNothingFitsWhole) {
  const PanelSizer size = linear({700, 500});
  const std::vector<ScreenBox> car{ScreenBox(Eigen::Vector2f(550, 330), Eigen::Vector2f(730, 420))};
  const PanelSpot spot = placeClear(kArea, car, 12.0f, size);
  EXPECT_LT(spot.scale, 1.0f);
  EXPECT_GT(spot.scale, 0.6f);  // beside the car there is room for most of it
  const ScreenBox panel = boxAt(spot, size);
  EXPECT_FALSE(boxesOverlap(panel, grown(car[0], 12.0f)));
  EXPECT_TRUE(kArea.contains(panel));
}

// Text rounds to whole pixels, so a shrunk panel can be a little larger than its factor says: the
// size is measured again until it fits.
TEST(PanelPlace, ShrinkingMeasuresTheSizeAgain) {
  const PanelSizer lumpy = [](float scale) {
    return Eigen::Vector2f(std::ceil(70.0f * scale) * 10.0f, std::ceil(50.0f * scale) * 10.0f);
  };
  const std::vector<ScreenBox> car{ScreenBox(Eigen::Vector2f(550, 330), Eigen::Vector2f(730, 420))};
  const PanelSpot spot = placeClear(kArea, car, 12.0f, lumpy);
  const ScreenBox panel = boxAt(spot, lumpy);
  EXPECT_FALSE(boxesOverlap(panel, grown(car[0], 12.0f)));
  EXPECT_TRUE(kArea.contains(panel));
}

// Seeded random cars, bays and panels: wherever placeClear does not have to go below the smallest
// factor, the panel is inside the area and clear of every box; it is whole when a band holds it.
TEST(PanelPlace, RandomLayoutsAreClearOrAtTheSmallestSize) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> x(0.0f, 1280.0f), y(100.0f, 680.0f), w(20.0f, 300.0f),
      pw(50.0f, 900.0f), ph(30.0f, 500.0f);
  int clear = 0;
  for (int i = 0; i < 5000; ++i) {
    std::vector<ScreenBox> avoid;
    for (int k = 0; k < 1 + i % 3; ++k) {
      const Eigen::Vector2f lo(x(rng), y(rng));
      avoid.emplace_back(lo, lo + Eigen::Vector2f(w(rng), w(rng)));
    }
    const PanelSizer size = linear({pw(rng), ph(rng)});
    const PanelSpot spot = placeClear(kArea, avoid, 10.0f, size, Eigen::Vector2f(x(rng), y(rng)));
    ASSERT_LE(spot.scale, 1.0f);
    ASSERT_GE(spot.scale, kMinPanelScale);
    const ScreenBox panel = boxAt(spot, size);
    if (spot.scale > kMinPanelScale) {
      ++clear;
      EXPECT_TRUE(kArea.contains(panel)) << i;
      for (const ScreenBox& b : avoid) {
        EXPECT_FALSE(boxesOverlap(panel, grown(b, 10.0f)))
            << i << " panel " << panel.min().transpose() << " - " << panel.max().transpose()
            << " scale " << spot.scale << " box " << b.min().transpose() << " - "
            << b.max().transpose();
      }
    }
  }
  EXPECT_GT(clear, 4000);
}

// --- Every level, as the game frames it --------------------------------------------------------

// The panel drawn behind the text call `text` (the last fill before it), as a box.
std::optional<ScreenBox> backdropBox(const RecordingCanvas& canvas, const std::string& text) {
  const RecordingCanvas::Text* t = canvas.lastText(text);
  if (t == nullptr) return std::nullopt;
  const RecordingCanvas::Fill* found = nullptr;
  for (const RecordingCanvas::Fill& f : canvas.fills) {
    if (f.order < t->order && (found == nullptr || f.order > found->order)) found = &f;
  }
  if (found == nullptr) return std::nullopt;
  ScreenBox box;
  for (const Eigen::Vector2f& p : found->points) box.extend(p);
  return box;
}

ScreenBox screenBoxOf(const Camera& camera, const Obb2& box) {
  const auto [lo, hi] = screenRect(camera, box);
  return {lo, hi};
}

// Draws the frame with PAUSED, then with the help, each time with the task (`view`'s, whose
// clock has not run), and checks that none of the three panels covers the car or the bay.
void expectPanelsClear(const World& world, const Camera& camera, const GoalView& view,
                       const std::string& task, const std::string& what) {
  const Goal& goal = view.challenge->goal();
  const ScreenBox car = screenBoxOf(camera, world.carBox());
  const ScreenBox bay = screenBoxOf(camera, Obb2::fromDegrees(goal.bay.center, goal.bay.heading_deg,
                                                              goal.bay.length, goal.bay.width));
  for (const bool help : {false, true}) {
    DrawOptions options;
    options.goal = &view;
    options.paused = true;
    options.help = help;
    options.sprites = true;
    RecordingCanvas canvas(camera.viewport);
    drawFrame(canvas, world, camera, world.carBox(), options);
    // With the help, the task is in it (and not drawn again beside it).
    std::vector<std::string> texts{help ? "Keys" : "PAUSED"};
    if (!help) texts.push_back(task);
    for (const std::string& text : texts) {
      const std::optional<ScreenBox> panel = backdropBox(canvas, text);
      ASSERT_TRUE(panel.has_value()) << what << ": no panel behind \"" << text << "\"";
      EXPECT_FALSE(boxesOverlap(*panel, car)) << what << ": \"" << text << "\" covers the car";
      EXPECT_FALSE(boxesOverlap(*panel, bay)) << what << ": \"" << text << "\" covers the bay";
      const Eigen::Vector2f vp = camera.viewport.cast<float>();
      EXPECT_TRUE(ScreenBox(Eigen::Vector2f::Zero(), vp).contains(*panel)) << what << " " << text;
    }
  }
}

// A level's: a challenge that has just started watching, so the clock has not run.
void expectPanelsClear(const World& world, const Camera& camera, const std::string& what) {
  ParkingChallenge fresh(*world.scene().goal, world.settings().hz, world.scene().player.health);
  fresh.observe(world);
  GoalView view;
  view.challenge = &fresh;
  expectPanelsClear(world, camera, view, world.scene().level->task, what);
}

TEST(PanelPlace, NoPanelCoversTheBayOrTheCarInAnyLevel) {
  const std::filesystem::path assets = std::filesystem::path(CARDEMO_SOURCE_DIR) / "assets";
  int levels = 0;
  for (const auto& entry : std::filesystem::directory_iterator(assets / "scenes/levels")) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().stem().string();
    const std::filesystem::path replay_path = assets / "replays" / (name + ".replay");
    const Parsed<Scene> scene = loadScene(entry.path().string());
    ASSERT_TRUE(scene.ok()) << scene.error().toString();
    const Parsed<Replay> replay = loadReplay(replay_path.string());
    ASSERT_TRUE(replay.ok()) << name << ": every level has a golden replay";
    ASSERT_TRUE(scene.value().goal && scene.value().level) << name;
    ++levels;
    for (const Eigen::Vector2i& vp : {Eigen::Vector2i(1024, 768), Eigen::Vector2i(1280, 720)}) {
      const std::string at = name + " " + std::to_string(vp.x()) + "x" + std::to_string(vp.y());
      World world(scene.value(), settingsForReplay(replay.value()));
      CameraRig rig(world, vp);
      expectPanelsClear(world, rig.camera(vp), at + " at the start");
      // The golden drive up to its parked frame, the rig following as in the game.
      std::optional<ParkingChallenge> challenge = startChallenge(world);
      for (const InputRun& run : replay.value().runs) {
        for (std::int64_t i = 0; i < run.count && !challenge->over(); ++i) {
          world.step(run.keys);
          rig.step(world);
          challenge->observe(world);
        }
      }
      ASSERT_TRUE(challenge->parkedFrame().has_value()) << at;
      expectPanelsClear(world, rig.camera(vp), at + " parked");
    }
  }
  EXPECT_GE(levels, 6);
}

// Free drive: each bay of the lot's chain highlighted in turn, along the bundled drives of the
// lot, at two window sizes. (The chain's clock is the one of a chain that has just started
// watching, so its task is drawn.)
TEST(PanelPlace, NoPanelCoversTheHighlightedBayOrTheCarInFreeDrive) {
  const std::filesystem::path assets = std::filesystem::path(CARDEMO_SOURCE_DIR) / "assets";
  int checked = 0;
  for (const char* name : {"demo", "head-on", "reverse"}) {
    const Parsed<Replay> replay = loadReplay((assets / "replays" / name).string() + ".replay");
    ASSERT_TRUE(replay.ok()) << replay.error().toString();
    const Parsed<Scene> scene = loadScene((assets / "scenes/parking-lot.json").string());
    ASSERT_TRUE(scene.ok()) << scene.error().toString();
    for (const Eigen::Vector2i& vp : {Eigen::Vector2i(1024, 768), Eigen::Vector2i(1280, 720)}) {
      World world(scene.value(), settingsForReplay(replay.value()));
      CameraRig rig(world, vp);
      std::int64_t frame = 0;
      for (const InputRun& run : replay.value().runs) {
        for (std::int64_t i = 0; i < run.count; ++i, ++frame) {
          if (frame % 240 == 0) {
            const BayChain chain = startBayChain(world);
            ASSERT_EQ(chain.bays().size(), 6u);
            for (const FreeBay& bay : chain.bays()) {
              ParkingChallenge highlighted(chainGoal(bay.bay, chain.settings()),
                                           world.settings().hz, world.scene().player.health);
              highlighted.observe(world);
              GoalView view;
              view.challenge = &highlighted;
              view.chain = &chain;
              expectPanelsClear(world, rig.camera(vp), view, chainTaskText(),
                                std::string(name) + " frame " + std::to_string(frame) + " " +
                                    bay.id + " " + std::to_string(vp.x()));
              ++checked;
            }
          }
          world.step(run.keys);
          rig.step(world);
        }
      }
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace cardemo
