// Drawing through a recording canvas: what is drawn where, in which colour, with no SDL.

#include "render/draw_world.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>

#include "../sim/scene_builders.hpp"
#include "io/replay_runner.hpp"
#include "io/replay_text.hpp"
#include "recording_canvas.hpp"
#include "render/debug_overlay.hpp"
#include "render/goal_overlay.hpp"
#include "render/hud.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::RecordingCanvas;
using test::sceneWith;

const Eigen::Vector2i kViewport{1280, 720};

RecordingCanvas drawn(const World& world, const Camera& camera, const DrawOptions& options = {},
                      const Obb2* player_box = nullptr) {
  RecordingCanvas canvas(camera.viewport);
  drawFrame(canvas, world, camera, player_box ? *player_box : world.carBox(), options);
  return canvas;
}

TEST(DrawWorld, PlayerDrawnInItsColourAtTheProjectedBox) {
  World world(sceneWith({parkedCar("A", 10, 0, 90)}, 3.0, -2.0, 30.0));
  Camera camera;
  camera.center = {1.0, 1.0};
  camera.pixels_per_metre = 20.0;
  const RecordingCanvas canvas = drawn(world, camera);
  const auto player = canvas.fillsOf(Palette{}.player);
  ASSERT_EQ(player.size(), 1u);
  ASSERT_EQ(player[0].points.size(), 4u);
  const auto corners = world.carBox().corners();
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LT((player[0].points[i] - camera.toScreen(corners[i])).norm(), 1e-3f);
  }
}

TEST(DrawWorld, FollowCameraPutsThePlayerAtTheScreenCentre) {
  World world(sceneWith({}, 123.0, -45.0, 70.0));
  const Camera camera = followCamera(world.carBox(), 15.0, kViewport);
  const auto player = drawn(world, camera).fillsOf(Palette{}.player);
  ASSERT_EQ(player.size(), 1u);
  EXPECT_LT((player[0].centroid() - Eigen::Vector2f{640.0f, 360.0f}).norm(), 1e-3f);
}

TEST(DrawWorld, InterpolatedPlayerBoxIsTheOneDrawn) {
  World world(sceneWith({}));
  const Obb2 between = Obb2::fromDegrees({0.5, 0.25}, 10.0, 4.5, 1.8);
  Camera camera;
  camera.viewport = kViewport;
  const auto player = drawn(world, camera, {}, &between).fillsOf(Palette{}.player);
  ASSERT_EQ(player.size(), 1u);
  EXPECT_LT((player[0].centroid() - camera.toScreen(between.center)).norm(), 1e-3f);
}

TEST(DrawWorld, ParkedCarsInViewDrawnInTheParkedColourWithWindscreens) {
  World world(sceneWith(
      {parkedCar("A", 10, 0, 90), parkedCar("B", -12, 6, 0), parkedCar("far", 5000, 0, 0)}));
  Camera camera;
  camera.viewport = kViewport;
  const RecordingCanvas canvas = drawn(world, camera);
  const auto a = canvas.fillsOf(parkedColor("A"));
  const auto b = canvas.fillsOf(parkedColor("B"));
  for (const auto& f : canvas.fills) {  // the far one is culled
    EXPECT_GT((f.centroid() - camera.toScreen({5000.0, 0.0})).norm(), 1000.0f);
  }
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  EXPECT_LT((a[0].centroid() - camera.toScreen({10.0, 0.0})).norm(), 1e-3f);
  EXPECT_LT((b.back().centroid() - camera.toScreen({-12.0, 6.0})).norm(), 1e-3f);
  // One windscreen per car drawn (two parked + the player).
  EXPECT_EQ(canvas.fillsOf(Palette{}.windscreen).size(), 3u);
}

TEST(DrawWorld, SpritesAreTintedImagesAndVectorsRemainTheFallback) {
  Scene scene = sceneWith({parkedCar("A", 10, 0, 90), parkedCar("B", -12, 6, 0)}, 0.0, 0.0, 30.0);
  scene.bounds = Aabb2{{-40.0, -30.0}, {40.0, 30.0}};
  World world(std::move(scene));
  Camera camera;
  camera.viewport = kViewport;
  camera.pixels_per_metre = 12.0;
  DrawOptions options;
  options.sprites = true;
  RecordingCanvas canvas(kViewport);
  canvas.with_images = true;
  drawFrame(canvas, world, camera, world.carBox(), options);
  const auto bodies = canvas.imagesOf(ImageId::kCarBody);
  ASSERT_EQ(bodies.size(), 3u);
  EXPECT_EQ(bodies[0].tint, parkedColor("A"));
  EXPECT_EQ(bodies[1].tint, parkedColor("B"));
  EXPECT_EQ(bodies[2].tint, Palette{}.player);
  // The player's body: at its box, 4.5 x 1.8 m, turned 30 degrees (clockwise on screen: -30).
  EXPECT_LT((bodies[2].center - camera.toScreen({0.0, 0.0})).norm(), 1e-3f);
  EXPECT_NEAR(bodies[2].size.x(), 4.5f * 12.0f, 1e-3f);
  EXPECT_NEAR(bodies[2].size.y(), 1.8f * 12.0f, 1e-3f);
  EXPECT_NEAR(bodies[2].angle, -30.0f * 3.14159265f / 180.0f, 1e-5f);
  EXPECT_EQ(canvas.imagesOf(ImageId::kWheel).size(), 12u);
  EXPECT_FALSE(canvas.imagesOf(ImageId::kGround).empty());
  EXPECT_TRUE(canvas.fillsOf(Palette{}.player).empty());  // no vector body under the sprite

  // Asked for sprites but the canvas has none: the vector cars are drawn.
  RecordingCanvas plain(kViewport);
  drawFrame(plain, world, camera, world.carBox(), options);
  EXPECT_TRUE(plain.images.empty());
  EXPECT_EQ(plain.fillsOf(Palette{}.player).size(), 1u);
}

TEST(DrawWorld, FrontTyresTurnWithTheSteering) {
  World world(sceneWith({}));
  InputFrame left;
  left.left = true;
  for (int i = 0; i < 30; ++i) world.step(left);
  ASSERT_GT(world.car().steer, 0.1);
  Camera camera;
  camera.viewport = kViewport;
  camera.center = world.car().position;
  camera.pixels_per_metre = 30.0;
  const RecordingCanvas canvas = drawn(world, camera);
  const auto tyres = canvas.fillsOf(Palette{}.tyre);
  ASSERT_EQ(tyres.size(), 4u);
  // Screen angle of each tyre's long side against the car's heading (screen y is flipped).
  auto turn = [&](const RecordingCanvas::Fill& f) {
    // Corners run counter-clockwise from local (+x, -y): corner 2 to corner 1 points along +x.
    const Eigen::Vector2f d = f.points[1] - f.points[2];
    const double tyre = std::atan2(-d.y(), d.x());
    return std::remainder(tyre - world.car().heading, 3.14159265358979323846);
  };
  EXPECT_NEAR(turn(tyres[0]), world.car().steer, 1e-4);
  EXPECT_NEAR(turn(tyres[1]), world.car().steer, 1e-4);
  EXPECT_NEAR(turn(tyres[2]), 0.0, 1e-4);
  EXPECT_NEAR(turn(tyres[3]), 0.0, 1e-4);
}

TEST(DrawWorld, WindscreenSitsTowardsTheHeading) {
  for (double heading : {0.0, 90.0, 180.0, -45.0}) {
    World world(sceneWith({}, 0.0, 0.0, heading));
    Camera camera;
    camera.viewport = kViewport;
    camera.pixels_per_metre = 30.0;
    const RecordingCanvas canvas = drawn(world, camera);
    const auto glass = canvas.fillsOf(Palette{}.windscreen);
    ASSERT_EQ(glass.size(), 1u);
    const Eigen::Vector2f d = glass[0].centroid() - camera.toScreen({0.0, 0.0});
    const double rad = heading * 3.14159265358979323846 / 180.0;
    // Screen y points down, so the heading's y flips.
    const Eigen::Vector2f expected{static_cast<float>(std::cos(rad)),
                                   static_cast<float>(-std::sin(rad))};
    EXPECT_GT(d.normalized().dot(expected), 0.99f) << "heading " << heading;
  }
}

TEST(DrawWorld, ObstaclesAndWallsAreDrawn) {
  Scene scene = sceneWith({});
  scene.bounds = Aabb2{{-20.0, -10.0}, {20.0, 10.0}};
  const std::array<Eigen::Vector2d, 3> tri{{{5, 5}, {8, 5}, {6, 8}}};
  scene.obstacles.push_back({"kerb", *ConvexPolygon::fromPoints(tri)});
  World world(std::move(scene));
  Camera camera;
  camera.viewport = kViewport;
  const RecordingCanvas canvas = drawn(world, camera);
  ASSERT_EQ(canvas.fillsOf(Palette{}.obstacle).size(), 1u);
  EXPECT_EQ(canvas.fillsOf(Palette{}.obstacle)[0].points.size(), 3u);
  EXPECT_EQ(canvas.fillsOf(Palette{}.wall).size(), 4u);
  EXPECT_EQ(canvas.cleared, Palette{}.outside);
  EXPECT_EQ(canvas.fillsOf(Palette{}.ground).size(), 1u);  // the lot inside the walls
}

// An obstacle at most kPostMaxSize across (a bollard, a pillar) is painted in the post colour with
// a lighter cap; a larger one keeps the obstacle colour.
TEST(DrawWorld, SmallObstaclesAreDrawnAsPosts) {
  Scene scene = sceneWith({});
  const std::array<Eigen::Vector2d, 4> post{
      {{0, 0}, {kPostMaxSize, 0}, {kPostMaxSize, 0.5}, {0, 0.5}}};
  const std::array<Eigen::Vector2d, 4> kerb{
      {{3, 0}, {3 + 1.001 * kPostMaxSize, 0}, {3 + 1.001 * kPostMaxSize, 0.2}, {3, 0.2}}};
  scene.obstacles.push_back({"bollard", *ConvexPolygon::fromPoints(post)});
  scene.obstacles.push_back({"kerb", *ConvexPolygon::fromPoints(kerb)});
  World world(std::move(scene));
  Camera camera;
  camera.viewport = kViewport;
  const RecordingCanvas canvas = drawn(world, camera);
  ASSERT_EQ(canvas.fillsOf(Palette{}.post).size(), 1u);
  EXPECT_EQ(canvas.fillsOf(Palette{}.post)[0].points.size(), 4u);
  EXPECT_EQ(canvas.fillsOf(shade(Palette{}.post, 1.2)).size(), 1u);  // the cap
  EXPECT_EQ(canvas.fillsOf(Palette{}.obstacle).size(), 1u);          // the kerb
}

TEST(DrawWorld, DebugOverlayAddsGreenAabbAndRedObbs) {
  World world(sceneWith({parkedCar("A", 10, 0, 90), parkedCar("B", -10, 0, 90)}));
  Camera camera;
  camera.viewport = kViewport;
  const OverlayPalette overlay;
  const RecordingCanvas plain = drawn(world, camera);
  EXPECT_EQ(plain.linesOf(overlay.aabb), 0u);
  EXPECT_EQ(plain.linesOf(overlay.obb), 0u);
  DrawOptions options;
  options.debug_overlay = true;
  const RecordingCanvas debug = drawn(world, camera, options);
  EXPECT_EQ(debug.linesOf(overlay.aabb), 4u);
  EXPECT_EQ(debug.linesOf(overlay.obb), 12u);  // two parked cars and the player
  EXPECT_TRUE(debug.hasText("narrow-phase tests"));
  EXPECT_TRUE(debug.hasText("candidates"));
}

TEST(DrawWorld, DebugOverlayHighlightsCandidatesAndContacts) {
  // The player's front overlaps A at frame 0: A is a candidate and a contact.
  World world(sceneWith({parkedCar("A", 3.0, 0, 90)}));
  ASSERT_FALSE(world.candidates().empty());
  ASSERT_FALSE(world.contacts().empty());
  Camera camera;
  camera.viewport = kViewport;
  camera.pixels_per_metre = 30.0;
  DrawOptions options;
  options.debug_overlay = true;
  const OverlayPalette overlay;
  const RecordingCanvas canvas = drawn(world, camera, options);
  EXPECT_EQ(canvas.linesOf(overlay.candidate), 4u);
  // Each contact: a normal arrow and a minimum-translation arrow (shaft + filled head).
  EXPECT_EQ(canvas.linesOf(overlay.normal), world.contacts().size());
  EXPECT_EQ(canvas.linesOf(overlay.mtv), world.contacts().size());
  // The normal points from the player (at the centre) towards A (screen +x).
  for (const auto& l : canvas.lines) {
    if (l.color == overlay.normal) {
      EXPECT_GT(l.b.x(), l.a.x());
    }
    if (l.color == overlay.mtv) {
      EXPECT_LT(l.b.x(), l.a.x());
    }
  }
}

TEST(Camera, RoundTripNearAndFarFromTheOrigin) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> offset(-50.0, 50.0);
  for (double far : {0.0, 1e5, 1e7, -1e7}) {
    Camera camera;
    camera.center = {far + 0.123, -far + 0.456};
    camera.pixels_per_metre = 12.0;
    for (int i = 0; i < 1000; ++i) {
      const Eigen::Vector2d w = camera.center + Eigen::Vector2d{offset(rng), offset(rng)};
      const Eigen::Vector2d back = camera.toWorld(camera.toScreen(w));
      // A float pixel near 1e3 is good to ~1e-4 px, i.e. well under a millimetre here.
      EXPECT_LT((back - w).norm(), 1e-4) << "at " << far;
    }
    EXPECT_LT((camera.toScreen(camera.center) - Eigen::Vector2f{640.0f, 360.0f}).norm(), 1e-4f);
  }
}

TEST(Camera, ScreenYPointsDown) {
  Camera camera;
  EXPECT_LT(camera.toScreen({0.0, 1.0}).y(), camera.toScreen({0.0, 0.0}).y());
  EXPECT_GT(camera.toScreen({1.0, 0.0}).x(), camera.toScreen({0.0, 0.0}).x());
}

TEST(DrawWorld, GridLinesLandOnWholeMetresFarFromTheOrigin) {
  Scene scene = sceneWith({}, 1e7 + 0.37, -1e7 + 0.81, 0.0);
  World world(std::move(scene));
  const Camera camera = followCamera(world.carBox(), 20.0, kViewport);
  DrawOptions debug;
  debug.debug_overlay = true;  // the grid is part of the overlay
  const RecordingCanvas canvas = drawn(world, camera, debug);
  const Palette palette;
  int vertical = 0;
  for (const auto& l : canvas.lines) {
    if (l.color != palette.grid || l.a.x() != l.b.x()) continue;
    ++vertical;
    const double x = camera.toWorld(l.a).x();
    EXPECT_NEAR(x, std::round(x), 1e-4);
  }
  EXPECT_GT(vertical, 40);  // 64 m in view, minus the 10 m lines drawn brighter
  EXPECT_LT(vertical, 80);
  const auto player = canvas.fillsOf(palette.player);
  ASSERT_EQ(player.size(), 1u);
  EXPECT_LT((player[0].centroid() - Eigen::Vector2f{640.0f, 360.0f}).norm(), 1e-3f);
}

TEST(DrawWorld, ZoomedFarOutSkipsTheMinorGrid) {
  World world(sceneWith({}));
  const Camera camera = followCamera(world.carBox(), 1.0, kViewport);
  DrawOptions debug;
  debug.debug_overlay = true;
  const RecordingCanvas canvas = drawn(world, camera, debug);
  EXPECT_EQ(canvas.linesOf(Palette{}.grid), 0u);
  EXPECT_GT(canvas.lines.size(), 100u);  // the 10 m lines (20 px apart) remain
}

TEST(Hud, HealthBarFillIsProportionalToHealth) {
  for (int health : {100, 73, 25, 1}) {
    RecordingCanvas canvas;
    drawHealthBar(canvas, {10.0f, 10.0f}, {200.0f, 20.0f}, health, 100);
    const auto fill = canvas.fillsOf(healthColor(health / 100.0));
    ASSERT_EQ(fill.size(), 1u) << health;
    EXPECT_NEAR(fill[0].width(), 2.0f * health, 1e-3f);
    EXPECT_TRUE(canvas.hasText(std::to_string(health) + " / 100"));
  }
  RecordingCanvas empty;
  drawHealthBar(empty, {10.0f, 10.0f}, {200.0f, 20.0f}, 0, 100);
  EXPECT_EQ(empty.fills.size(), 1u);  // the trough only
}

TEST(Hud, HealthBarInTheFrameFollowsTheWorldsHealth) {
  // A crash at 10 m/s into A takes health; contact at rest takes none.
  Scene scene = sceneWith({parkedCar("A", 8.0, 0, 90)});
  scene.player.speed = 10.0;
  World world(std::move(scene));
  for (int i = 0; i < 240 && world.hits().empty(); ++i) world.step(InputFrame{});
  ASSERT_LT(world.health(), 100);
  Camera camera;
  const RecordingCanvas canvas = drawn(world, camera);
  const auto fill = canvas.fillsOf(healthColor(world.health() / 100.0));
  ASSERT_EQ(fill.size(), 1u);
  EXPECT_NEAR(fill[0].width(), 240.0f * hudScale(kViewport) * world.health() / 100.0f, 1e-2f);
  EXPECT_LT(fill[0].centroid().x(), 300.0f);  // top left
  EXPECT_LT(fill[0].centroid().y(), 80.0f);
  EXPECT_TRUE(canvas.hasText("1"));  // one hit
}

TEST(Hud, HealthColourGoesFromRedToGreen) {
  const Rgba full = healthColor(1.0);
  const Rgba empty = healthColor(0.0);
  EXPECT_GT(full.g, full.r);
  EXPECT_GT(empty.r, empty.g);
  EXPECT_EQ(healthColor(2.0), full);
  EXPECT_EQ(healthColor(-1.0), empty);
}

TEST(Hud, APlayerSeesSpeedAndCrashesTheOverlayAddsFrameHitsAndFps) {
  World world(sceneWith({}));
  Camera camera;
  DrawOptions playing;
  playing.fps = 59.6;
  const RecordingCanvas plain = drawn(world, camera, playing);
  EXPECT_TRUE(plain.hasText("km/h"));
  EXPECT_TRUE(plain.hasText("Crashes"));
  EXPECT_FALSE(plain.hasText("Hits"));
  EXPECT_FALSE(plain.hasText("Frame"));
  EXPECT_FALSE(plain.hasText("FPS"));
  playing.debug_overlay = true;
  const RecordingCanvas overlay = drawn(world, camera, playing);
  EXPECT_TRUE(overlay.hasText("Frame"));
  EXPECT_TRUE(overlay.hasText("Hits"));
  EXPECT_TRUE(overlay.hasText("FPS"));
  DrawOptions rendered;
  rendered.frame_counter = true;
  EXPECT_TRUE(drawn(world, camera, rendered).hasText("Frame"));
  EXPECT_FALSE(drawn(world, camera, rendered).hasText("FPS"));
}

TEST(Hud, ShowsSpeedFrameFpsPlaybackStatusAndPaused) {
  World world(sceneWith({}));
  Camera camera;
  EXPECT_FALSE(drawn(world, camera).hasText("FPS"));
  EXPECT_FALSE(drawn(world, camera).hasText("PAUSED"));
  DrawOptions options;
  options.debug_overlay = true;
  options.fps = 59.6;
  options.playback_speed = 2.0;
  options.paused = true;
  options.status = "recording to drive.replay";
  const RecordingCanvas canvas = drawn(world, camera, options);
  for (const char* text : {"km/h", "Crashes", "Hits", "Frame", "FPS", "60", "2x", "PAUSED",
                           "recording to drive.replay"}) {
    EXPECT_TRUE(canvas.hasText(text)) << text;
  }
}

TEST(Hud, SpeedReadsStoppedOnceTheRunIsOver) {
  Scene scene = sceneWith({});
  scene.player.speed = 5.0;
  World world(std::move(scene));
  Camera camera;
  EXPECT_TRUE(drawn(world, camera).hasText("18.0 km/h"));
  DrawOptions options;
  options.run_over = true;
  const RecordingCanvas canvas = drawn(world, camera, options);
  EXPECT_TRUE(canvas.hasText("stopped"));
  EXPECT_FALSE(canvas.hasText("18.0 km/h"));
}

TEST(Hud, SpeedHasItsSignAndOneDecimal) {
  EXPECT_EQ(speedText(5.0), "18.0 km/h");
  EXPECT_EQ(speedText(-0.8889), "-3.2 km/h");
  EXPECT_EQ(speedText(0.0), "0.0 km/h");
  EXPECT_EQ(speedText(-0.01), "0.0 km/h");  // never "-0.0"
  EXPECT_EQ(speedText(0.01), "0.0 km/h");
  Scene scene = sceneWith({});
  scene.player.speed = -0.8889;
  World world(std::move(scene));
  EXPECT_TRUE(drawn(world, Camera{}).hasText("-3.2 km/h"));
}

// The gear row's value: the text drawn right of the "Gear" label, on its line.
std::string gearShown(const RecordingCanvas& canvas) {
  const auto* label = canvas.lastText("Gear");
  if (label == nullptr) return "?";
  for (const auto& t : canvas.texts) {
    if (t.at.y() == label->at.y() && t.at.x() > label->at.x() && t.text.size() == 1) return t.text;
  }
  return "?";
}

TEST(Hud, ShowsTheGearDrivingReversingOrNeutral) {
  Scene scene = sceneWith({});
  World world(scene);
  const Camera camera;
  EXPECT_EQ(gearShown(drawn(world, camera)), "N");
  world.step(InputFrame{false, true, false, false});  // Down at a standstill: reverse
  EXPECT_EQ(gearShown(drawn(world, camera)), "R");
  for (int i = 0; i < 120; ++i) world.step(InputFrame{false, true, false, false});
  const RecordingCanvas reversing = drawn(world, camera);
  EXPECT_EQ(gearShown(reversing), "R");
  ASSERT_NE(reversing.lastText("km/h"), nullptr);
  EXPECT_EQ(reversing.lastText("km/h")->text.front(), '-');
  World forward(scene);
  forward.step(InputFrame{true, false, false, false});
  EXPECT_EQ(gearShown(drawn(forward, camera)), "D");
  // Held at a standstill by Down pressed while moving forward: neutral.
  for (int i = 0; i < 60; ++i) forward.step(InputFrame{true, false, false, false});
  for (int i = 0; i < 240; ++i) forward.step(InputFrame{false, true, false, false});
  ASSERT_EQ(forward.car().speed, 0.0);
  EXPECT_EQ(gearShown(drawn(forward, camera)), "N");
}

// One health point and 10 m/s towards a parked car 8 m ahead: run until the game is over.
World crashedWorld() {
  Scene scene = sceneWith({parkedCar("A", 8.0, 0, 90)});
  scene.player.health = 1;
  scene.player.speed = 10.0;
  World world(std::move(scene));
  for (int i = 0; i < 240 && !world.gameOver(); ++i) world.step(InputFrame{});
  return world;
}

TEST(Hud, GameOverPanelAtZeroHealth) {
  World world = crashedWorld();
  ASSERT_TRUE(world.gameOver());
  Camera camera;
  camera.center = world.car().position;
  EXPECT_TRUE(drawn(world, camera).hasText("GAME OVER"));
  World alive(sceneWith({}));
  EXPECT_FALSE(drawn(alive, camera).hasText("GAME OVER"));
}

TEST(Hud, HelpPanelListsEveryKey) {
  World world(sceneWith({}));
  Camera camera;
  DrawOptions options;
  options.help = true;
  const RecordingCanvas canvas = drawn(world, camera, options);
  for (const char* key : {"Up", "Down", "Left", "Right", "P", "N", "R", "B", "F1", "F12", "+", "-",
                          "[", "]", "Esc"}) {
    EXPECT_TRUE(canvas.hasText(key)) << key;
  }
  EXPECT_FALSE(drawn(world, camera).hasText("F12"));
  // The keys of the end of a run: retry, next level, back to the picker.
  for (const char* what : {"retry after the run ends (PARKED, TIME UP, GAME OVER)",
                           "step one frame while paused; once parked: next level",
                           "back to the level list (when started from it), else quit"}) {
    EXPECT_TRUE(canvas.hasText(what)) << what;
  }
}

TEST(Hud, HelpPanelShowsTheLevelsTask) {
  Scene scene = sceneWith({});
  scene.level = LevelInfo{2, "Reverse bay", "Reverse into the bay, facing out"};
  const World level(scene);
  Camera camera;
  DrawOptions options;
  options.help = true;
  EXPECT_TRUE(drawn(level, camera, options).hasText("Task: Reverse into the bay, facing out"));
  EXPECT_FALSE(drawn(World(sceneWith({})), camera, options).hasText("Task:"));
}

TEST(Hud, GameOverPanelListsTheKeysItIsGiven) {
  World world = crashedWorld();
  ASSERT_TRUE(world.gameOver());
  Camera camera;
  camera.center = world.car().position;
  EXPECT_TRUE(drawn(world, camera).hasText("Enter restart    Esc quit"));
  DrawOptions options;
  options.game_over_keys = "Enter retry    Esc levels";
  const RecordingCanvas canvas = drawn(world, camera, options);
  EXPECT_TRUE(canvas.hasText("Enter retry    Esc levels"));
  EXPECT_FALSE(canvas.hasText("Enter restart    Esc quit"));
}

// A bundled replay run to its end.
World replayed(const std::string& name) {
  const std::string path = std::string(CARDEMO_SOURCE_DIR) + "/assets/replays/" + name;
  const Parsed<Replay> replay = loadReplay(path);
  EXPECT_TRUE(replay.ok()) << path;
  Parsed<Scene> scene = loadReplayScene(replay.value(), path, "");
  EXPECT_TRUE(scene.ok()) << path;
  World world(std::move(scene).value(), settingsForReplay(replay.value()));
  runReplayInputs(world, replay.value());
  return world;
}

// A bounce inside one crash, or a touch too gentle to cost anything, is not another crash for the
// player; the raw count of first touches stays a developer row.
TEST(Hud, CountsDamagingCrashesNotEveryTouch) {
  // head-on: one crash and its bounces; graze: touches below the damage threshold; garage: two
  // crashes, the second with a free re-touch.
  for (const char* name : {"head-on.replay", "graze.replay", "garage.replay"}) {
    const World world = replayed(name);
    std::set<std::int64_t> damaging;
    for (const HitEvent& h : world.hits()) {
      if (h.damage > 0) damaging.insert(h.crash);
    }
    ASSERT_LT(damaging.size(), world.hits().size()) << name << ": every touch is a crash";
    const std::string crashes = std::to_string(damaging.size());
    const Camera camera = followCamera(world.carBox(), 30.0, kViewport);
    const RecordingCanvas player = drawn(world, camera);
    EXPECT_EQ(player.rowValue("Crashes"), crashes) << name;
    EXPECT_FALSE(player.hasText("Hits")) << name;
    DrawOptions debug;
    debug.debug_overlay = true;
    const RecordingCanvas overlay = drawn(world, camera, debug);
    EXPECT_EQ(overlay.rowValue("Crashes"), crashes) << name;
    EXPECT_EQ(overlay.rowValue("Hits"), std::to_string(world.hits().size())) << name;
  }
}

TEST(Hud, GameOverPanelCountsCrashes) {
  World world = crashedWorld();
  ASSERT_TRUE(world.gameOver());
  const RecordingCanvas canvas = drawn(world, followCamera(world.carBox(), 20.0, kViewport));
  const RecordingCanvas::Text* title = canvas.lastText("GAME OVER");
  ASSERT_NE(title, nullptr);
  bool crashes_row = false;
  for (const auto& t : canvas.texts) {
    if (t.order < title->order) continue;
    EXPECT_NE(t.text, "Hits") << "the GAME OVER panel lists raw touches";
    crashes_row = crashes_row || t.text == "Crashes";
  }
  EXPECT_TRUE(crashes_row);
}

TEST(Hud, InsetsCoverThePlayersPanelAndTheStatusLine) {
  World world(sceneWith({}));
  for (const Eigen::Vector2i& vp : {Eigen::Vector2i(1280, 720), Eigen::Vector2i(640, 480),
                                    Eigen::Vector2i(1920, 1080), Eigen::Vector2i(3840, 2160)}) {
    RecordingCanvas canvas(vp);
    DrawOptions player;
    player.status = "attempt 3";
    const ViewInsets insets = hudInsets(vp);
    EXPECT_LE(drawHud(canvas, world, player).y(), insets.top) << vp.transpose();
    EXPECT_FLOAT_EQ(static_cast<float>(vp.y()) - insets.bottom, statusLineTop(vp));
  }
  // The level's timer at its tallest (with the readout's row) ends above the strip the HUD panel
  // sets, at every HUD scale: the strip, and so the camera's framing, is the panel's.
  for (int height = 240; height <= 2400; height += 7) {
    const Eigen::Vector2i vp{height * 16 / 9, height};
    RecordingCanvas canvas(vp);
    const float panel_bottom = drawHud(canvas, world, DrawOptions{}).y();
    EXPECT_FLOAT_EQ(hudInsets(vp).top, panel_bottom + 8.0f * hudScale(vp)) << height;
    EXPECT_LT(timerPanelBottom(vp), hudInsets(vp).top) << height;
  }
}

}  // namespace
}  // namespace cardemo
