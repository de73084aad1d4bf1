// The camera rig: clamped inside the walls, looking ahead along the velocity, fitted to the scene.

#include "render/camera_rig.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "../sim/scene_builders.hpp"
#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "io/scene_json.hpp"
#include "recording_canvas.hpp"
#include "render/hud.hpp"
#include "render/shapes.hpp"
#include "render/world_layer.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::sceneWith;

// The world rectangle a camera shows, exactly (no margin).
Aabb2 shown(const Camera& c) {
  const Eigen::Vector2d half =
      Eigen::Vector2d(c.viewport.x(), c.viewport.y()) * (0.5 / c.pixels_per_metre);
  return {c.center - half, c.center + half};
}

TEST(CameraRig, ClampKeepsTheViewInsideTheBoundsForRandomPoses) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-400.0, 400.0);
  std::uniform_real_distribution<double> size(5.0, 300.0);
  std::uniform_real_distribution<double> zoom(1.0, 60.0);
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector2d lo{pos(rng), pos(rng)};
    const Aabb2 bounds{lo, lo + Eigen::Vector2d{size(rng), size(rng)}};
    Camera c;
    c.center = {pos(rng), pos(rng)};
    c.pixels_per_metre = zoom(rng);
    c.viewport = {1280, 720};
    const Camera clamped = clampToBounds(c, bounds);
    const Aabb2 view = shown(clamped);
    for (int axis = 0; axis < 2; ++axis) {
      const double view_size = view.max[axis] - view.min[axis];
      const double lot_size = bounds.max[axis] - bounds.min[axis];
      if (view_size <= lot_size) {
        // Nothing beyond the walls is shown.
        EXPECT_GE(view.min[axis], bounds.min[axis] - 1e-9);
        EXPECT_LE(view.max[axis], bounds.max[axis] + 1e-9);
      } else {
        // A lot smaller than the view sits in the middle.
        EXPECT_NEAR(clamped.center[axis], 0.5 * (bounds.min[axis] + bounds.max[axis]), 1e-9);
      }
    }
    // A camera already inside stays put.
    const Camera again = clampToBounds(clamped, bounds);
    EXPECT_EQ(again.center, clamped.center);
  }
}

TEST(CameraRig, RigCameraNeverShowsVoidBeyondTheWallsOfALargeLot) {
  Scene scene = sceneWith({}, 0.0, 0.0, 0.0);
  scene.bounds = Aabb2{{-100.0, -60.0}, {100.0, 60.0}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-98.0, 98.0), y(-58.0, 58.0), h(-180.0, 180.0);
  for (int i = 0; i < 200; ++i) {
    Scene s = scene;
    s.player.position = {x(rng), y(rng)};
    s.player.heading_deg = h(rng);
    s.player.speed = 20.0;
    World world(std::move(s));
    CameraRig rig(world, {1280, 720});
    for (int k = 0; k < 30; ++k) {
      world.step(InputFrame{});
      rig.step(world);
    }
    const Camera c = rig.camera({1280, 720}, 0.5, 1.0, {15.0f, -15.0f});
    // Beyond the walls only under the HUD's strips.
    const ViewInsets hud = hudInsets(c.viewport);
    Aabb2 view = shown(c);
    view.max.y() -= hud.top / c.pixels_per_metre;
    view.min.y() += hud.bottom / c.pixels_per_metre;
    const Aabb2 walls = *cameraBounds(world.scene());
    EXPECT_GE(view.min.x(), walls.min.x() - 1e-9);
    EXPECT_GE(view.min.y(), walls.min.y() - 1e-9);
    EXPECT_LE(view.max.x(), walls.max.x() + 1e-9);
    EXPECT_LE(view.max.y(), walls.max.y() + 1e-9);
  }
}

TEST(CameraRig, LookAheadPointsAlongTheVelocity) {
  for (double heading : {0.0, 37.0, 90.0, -135.0, 180.0}) {
    Scene scene = sceneWith({}, 10.0, -5.0, heading);
    scene.player.speed = 15.0;
    World world(std::move(scene));
    CameraRig rig(world, {1280, 720});
    for (int k = 0; k < 240; ++k) {  // two seconds: the smoothing has caught up
      world.step(InputFrame{});
      rig.step(world);
    }
    const Eigen::Vector2d lead = rig.center() - world.car().position;
    const Eigen::Vector2d v = world.car().velocity();
    ASSERT_GT(v.norm(), 1.0);
    EXPECT_GT(lead.normalized().dot(v.normalized()), 0.999) << heading;
    const CameraRigSettings s;
    EXPECT_NEAR((rig.target() - world.car().position).norm(),
                std::min(s.max_look_ahead_m, v.norm() * s.look_ahead_s), 1e-9);
    // Faster means further out.
    EXPECT_LT(rig.speedZoom(), 1.0);
  }
  World still(sceneWith({}, 3.0, 4.0, 0.0));
  CameraRig rig(still, {1280, 720});
  // A car at rest is in the middle of the view between the HUD's strips.
  const ViewInsets hud = hudInsets({1280, 720});
  const Eigen::Vector2f car = rig.camera({1280, 720}).toScreen({3.0, 4.0});
  EXPECT_NEAR(car.x(), 640.0f, 1e-3f);
  EXPECT_NEAR(car.y(), 0.5f * (hud.top + 720.0f - hud.bottom), 1e-3f);
  CameraRigSettings whole;
  whole.clear_hud = false;
  EXPECT_EQ(CameraRig(still, {1280, 720}, whole).camera({1280, 720}).center,
            Eigen::Vector2d(3.0, 4.0));
  EXPECT_EQ(rig.speedZoom(), 1.0);
}

TEST(CameraRig, FittedZoomShowsTheWholeScene) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> size(2.0, 2000.0);
  std::uniform_int_distribution<int> px(64, 4000);
  for (int i = 0; i < 2000; ++i) {
    const Aabb2 area{{-size(rng), -size(rng)}, {size(rng), size(rng)}};
    const Eigen::Vector2i vp{px(rng), px(rng)};
    const double z = fittedZoom(area, vp, 1.0);
    Camera c;
    c.center = 0.5 * (area.min + area.max);
    c.pixels_per_metre = z;
    c.viewport = vp;
    const Aabb2 view = shown(c);
    EXPECT_LE(view.min.x(), area.min.x() + 1e-9);
    EXPECT_LE(view.min.y(), area.min.y() + 1e-9);
    EXPECT_GE(view.max.x(), area.max.x() - 1e-9);
    EXPECT_GE(view.max.y(), area.max.y() - 1e-9);
    // ...and is the largest such zoom: one axis is filled exactly.
    const Eigen::Vector2d ratio = (area.max - area.min).cwiseQuotient(view.max - view.min);
    EXPECT_NEAR(ratio.maxCoeff(), 1.0, 1e-9);
  }
}

TEST(CameraRig, BaseZoomIsFittedToTheSceneWithinLimits) {
  Scene garage = sceneWith({parkedCar("A", 5.0, 5.0, 0.0)});
  garage.bounds = Aabb2{{-18.0, -9.5}, {18.0, 9.5}};
  World world(std::move(garage));
  const CameraRig rig(world, {1280, 720});
  const CameraRigSettings s;
  const ViewInsets hud = hudInsets({1280, 720});
  EXPECT_NEAR(rig.baseZoom(),
              fittedZoom(*cameraBounds(world.scene()), {1280, 720}, s.fit_margin, hud), 1e-12);
  // A fitted garage shows all of it, clear of the HUD.
  const Camera c = rig.camera({1280, 720});
  const Aabb2 view = shown(c);
  EXPECT_LE(view.min.x(), -18.0 - kWallThicknessM + 1e-9);
  EXPECT_GE(view.max.y() - hud.top / c.pixels_per_metre, 9.5 + kWallThicknessM - 1e-9);
  EXPECT_LE(view.min.y() + hud.bottom / c.pixels_per_metre, -9.5 - kWallThicknessM + 1e-9);
  Scene big = sceneWith({});
  big.bounds = Aabb2{{-1000.0, -1000.0}, {1000.0, 1000.0}};
  EXPECT_EQ(CameraRig(World(std::move(big)), {1280, 720}).baseZoom(), s.min_fit_ppm);
}

// The free-drive lot (120 m x 80 m) fits the window at 9 px/m, where a car is 40 px long: the
// rig starts closer, at the levels' scale (the + and - keys still zoom from there).
TEST(CameraRig, BigLotStartsWithCarsAbout100PixelsLong) {
  Scene lot = sceneWith({});
  lot.bounds = Aabb2{{-60.0, -40.0}, {60.0, 40.0}};
  const World world(std::move(lot));
  for (const Eigen::Vector2i& vp : {Eigen::Vector2i(1280, 720), Eigen::Vector2i(1280, 800)}) {
    const Camera c = CameraRig(world, vp).camera(vp);
    EXPECT_GE(world.scene().player.length * c.pixels_per_metre, 100.0) << vp.transpose();
    EXPECT_LT(fittedZoom(*cameraBounds(world.scene()), vp, 1.04), c.pixels_per_metre);
  }
}

// The box is on screen, below the HUD panel at the top (and the timer beside it) and above the
// status line at the bottom.
void expectClearOfTheHud(const World& world, const Camera& c, const Obb2& box,
                         const std::string& what) {
  test::RecordingCanvas canvas(c.viewport);
  DrawOptions player;
  player.status = "attempt 2";
  const float hud_bottom = drawHud(canvas, world, player).y();
  const auto [lo, hi] = screenRect(c, box);
  EXPECT_GE(lo.x(), 0.0f) << what;
  EXPECT_LE(hi.x(), static_cast<float>(c.viewport.x())) << what;
  EXPECT_GE(lo.y(), hud_bottom) << what << ": under the HUD panel";
  EXPECT_LE(hi.y(), statusLineTop(c.viewport)) << what << ": under the status line";
}

// Every level, in the usual window shapes: at the start and once parked, the goal bay and the
// start are framed clear of the HUD's panels.
TEST(CameraRig, LevelsKeepTheBayAndTheStartClearOfTheHud) {
  const std::string dir = std::string(CARDEMO_SOURCE_DIR) + "/assets/";
  for (const char* level : {"level-1-straight", "level-2-reverse", "level-3-parallel",
                            "level-4-garage", "level-5-slalom", "level-6-turn"}) {
    const Parsed<Replay> replay = loadReplay(dir + "replays/" + level + ".replay");
    ASSERT_TRUE(replay.ok()) << level;
    const Parsed<Scene> scene = loadScene(dir + "scenes/levels/" + level + ".json");
    ASSERT_TRUE(scene.ok()) << level;
    const Scene& s = scene.value();
    ASSERT_TRUE(s.goal.has_value());
    const ParkingBay& bay = s.goal->bay;
    const Obb2 bay_box = Obb2::fromDegrees(bay.center, bay.heading_deg, bay.length, bay.width);
    const Obb2 start =
        Obb2::fromDegrees(s.player.position, s.player.heading_deg, s.player.length, s.player.width);
    for (const Eigen::Vector2i& vp : {Eigen::Vector2i(1280, 720), Eigen::Vector2i(1280, 800),
                                      Eigen::Vector2i(1920, 1080), Eigen::Vector2i(1024, 768)}) {
      const std::string at =
          std::string(level) + " at " + std::to_string(vp.x()) + "x" + std::to_string(vp.y());
      World world(s, settingsForReplay(replay.value()));
      CameraRig rig(world, vp);
      expectClearOfTheHud(world, rig.camera(vp), bay_box, at + ", start: the bay");
      expectClearOfTheHud(world, rig.camera(vp), start, at + ", start: the car");
      runReplayInputs(world, replay.value(), [&rig](const World& w) { rig.step(w); });
      expectClearOfTheHud(world, rig.camera(vp), bay_box, at + ", parked: the bay");
    }
  }
}

}  // namespace
}  // namespace cardemo
