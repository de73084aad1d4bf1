// Hit feedback and tyre marks: what appears after a hit, how it decays, and its bounds.

#include "render/effects.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"
#include "render/hud.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::RecordingCanvas;
using test::sceneWith;

InputFrame throttle() {
  InputFrame in;
  in.up = true;
  return in;
}

// Drives into a car parked 12 m ahead until the first hit; returns the frame of the hit.
std::int64_t driveIntoCar(World& world, Effects& fx) {
  while (world.hits().empty() && world.frame() < 2000) {
    world.step(throttle());
    fx.observe(world);
  }
  return world.hits().empty() ? -1 : world.hits().front().frame;
}

TEST(Effects, HitFlashShakeNumberPulseAndDentsAppearThenDecay) {
  World world(sceneWith({parkedCar("A", 12.0, 0.0, 90.0)}));
  Effects fx(world);
  EXPECT_EQ(fx.playerFlash(), 0.0f);
  EXPECT_EQ(fx.shake(), Eigen::Vector2f::Zero());
  ASSERT_GT(driveIntoCar(world, fx), 0);
  EXPECT_GT(fx.playerFlash(), 0.9f);
  EXPECT_GT(fx.colliderFlash(0), 0.9f);
  EXPECT_GT(fx.healthPulse(), 0.9f);
  EXPECT_GT(fx.shake().norm(), 0.0f);
  ASSERT_EQ(fx.numbers().size(), 1u);
  EXPECT_EQ(fx.numbers()[0].damage, world.hits()[0].damage);
  EXPECT_EQ(fx.healthBeforeHit(), world.health() + world.hits()[0].damage);
  // One dent on each car, at the contact side: the player's nose (+x), A's side facing -x.
  ASSERT_EQ(fx.dents().size(), 2u);
  EXPECT_EQ(fx.dents()[0].owner, kPlayerDent);
  EXPECT_NEAR(fx.dents()[0].local.x(), 2.25, 1e-9);
  EXPECT_EQ(fx.dents()[1].owner, 0u);
  // A stands at 90 degrees: its local +y axis, perp(axis) = (-1, 0), faces the player.
  EXPECT_NEAR(fx.dents()[1].local.y(), 0.9, 1e-9);

  // Everything but the dents fades within its frame count; timers count frames, not time.
  float last_flash = fx.playerFlash();
  for (int i = 0; i < 200; ++i) {
    world.step(InputFrame{});
    fx.observe(world);
    EXPECT_LE(fx.playerFlash(), last_flash);
    last_flash = fx.playerFlash();
  }
  EXPECT_EQ(fx.playerFlash(), 0.0f);
  EXPECT_EQ(fx.colliderFlash(0), 0.0f);
  EXPECT_EQ(fx.healthPulse(), 0.0f);
  EXPECT_EQ(fx.shake(), Eigen::Vector2f::Zero());
  EXPECT_TRUE(fx.numbers().empty());
  EXPECT_EQ(fx.dents().size(), 2u);
}

TEST(Effects, ATouchThatCostsNothingFlashesButLeavesNoNumberDentOrPulse) {
  // A car 5 cm beyond the player's nose; a short burst of throttle, then coasting into it at
  // well under the 1 m/s damage threshold.
  World world(sceneWith({parkedCar("A", 2.25 + 0.9 + 0.05, 0.0, 90.0)}));
  Effects fx(world);
  while (world.car().speed < 0.4 && world.frame() < 200) {
    world.step(throttle());
    fx.observe(world);
  }
  while (world.hits().empty() && world.frame() < 600) {
    world.step(InputFrame{});
    fx.observe(world);
  }
  ASSERT_EQ(world.hits().size(), 1u);
  ASSERT_EQ(world.hits()[0].damage, 0);
  EXPECT_GT(fx.playerFlash(), 0.9f);
  EXPECT_GT(fx.colliderFlash(0), 0.9f);
  EXPECT_TRUE(fx.numbers().empty());
  EXPECT_TRUE(fx.dents().empty());
  EXPECT_EQ(fx.healthPulse(), 0.0f);
  EXPECT_EQ(fx.shake(), Eigen::Vector2f::Zero());
}

TEST(Effects, ShakeGrowsWithDamageAndIsTheSameOnEveryRun) {
  auto shakeAfterHit = [](double distance) {
    World world(sceneWith({parkedCar("A", distance, 0.0, 90.0)}));
    Effects fx(world);
    driveIntoCar(world, fx);
    return std::make_pair(fx.shake(), world.hits().front().damage);
  };
  const auto [near_shake, near_damage] = shakeAfterHit(6.0);
  const auto [far_shake, far_damage] = shakeAfterHit(30.0);
  ASSERT_LT(near_damage, far_damage);  // a longer run-up hits harder
  const EffectsSettings s;
  // At the hit frame the amplitude is the full damage-scaled value along each axis at most.
  EXPECT_LE(near_shake.cwiseAbs().maxCoeff(), s.shake_px_per_damage * near_damage + 1e-4);
  EXPECT_LE(far_shake.cwiseAbs().maxCoeff(), s.max_shake_px + 1e-4);
  EXPECT_EQ(shakeAfterHit(30.0).first, far_shake);
}

TEST(Effects, ResetForgetsEverything) {
  World world(sceneWith({parkedCar("A", 12.0, 0.0, 90.0)}));
  Effects fx(world);
  driveIntoCar(world, fx);
  World fresh(sceneWith({parkedCar("A", 12.0, 0.0, 90.0)}));
  fx.reset(fresh);
  EXPECT_EQ(fx.playerFlash(), 0.0f);
  EXPECT_TRUE(fx.dents().empty());
  EXPECT_TRUE(fx.numbers().empty());
  EXPECT_EQ(fx.skidCount(), 0u);
}

TEST(Effects, SkidMarksAreBoundedAndHardStopsLayThem) {
  EffectsSettings settings;
  settings.max_skid_segments = 40;
  World world(sceneWith({}));
  Effects fx(world, settings);
  for (int lap = 0; lap < 6; ++lap) {
    for (int i = 0; i < 360; ++i) {
      world.step(throttle());
      fx.observe(world);
    }
    InputFrame brake;
    brake.down = true;
    bool marked = false;
    while (world.car().speed > 0.5) {
      world.step(brake);
      fx.observe(world);
      marked = marked || fx.marking();
      EXPECT_TRUE(fx.braking());
      EXPECT_LE(fx.skidCount(), settings.max_skid_segments);
    }
    EXPECT_TRUE(marked) << "lap " << lap;
  }
  EXPECT_EQ(fx.skidCount(), settings.max_skid_segments);
  // Oldest first: the newest mark is the last one, near the car.
  const SkidSegment& newest = fx.skid(fx.skidCount() - 1);
  EXPECT_LT((newest.b - world.car().position).norm(), 3.0);
  for (std::size_t i = 0; i < fx.skidCount(); ++i) {
    EXPECT_LE((fx.skid(i).b - fx.skid(i).a).norm(), 1.0);
  }
}

TEST(Effects, TyrePositionsSitInsideTheBodyAtTheAxles) {
  const Obb2 box = Obb2::fromDegrees({5.0, -3.0}, 30.0, 4.5, 1.8);
  const auto tyres = tyrePositions(box, 2.7);
  for (const auto& t : tyres) {
    const Eigen::Vector2d d = t - box.center;
    EXPECT_NEAR(std::abs(d.dot(box.axis)), 1.35, 1e-9);
    EXPECT_LT(std::abs(d.dot(box.perp())), 0.9);
  }
}

TEST(Effects, FeedbackIsDrawnAfterAHitAndGoneLater) {
  World world(sceneWith({parkedCar("A", 12.0, 0.0, 90.0)}));
  Effects fx(world);
  driveIntoCar(world, fx);
  Camera camera;
  camera.center = world.car().position;
  camera.pixels_per_metre = 20.0;
  DrawOptions options;
  options.effects = &fx;
  RecordingCanvas canvas(camera.viewport);
  drawFrame(canvas, world, camera, world.carBox(), options);
  const std::string number = "-" + std::to_string(world.hits()[0].damage);
  EXPECT_TRUE(canvas.hasText(number));
  std::size_t white = 0;  // the flash over both cars
  for (const auto& f : canvas.fills) white += f.color.r == 255 && f.color.g == 250 ? 1 : 0;
  EXPECT_EQ(white, 2u);
  for (int i = 0; i < 200; ++i) {
    world.step(InputFrame{});
    fx.observe(world);
  }
  drawFrame(canvas, world, camera, world.carBox(), options);
  EXPECT_FALSE(canvas.hasText(number));
  white = 0;
  for (const auto& f : canvas.fills) white += f.color.r == 255 && f.color.g == 250 ? 1 : 0;
  EXPECT_EQ(white, 0u);
}

// A hit that ends the game: once nothing is stepped the window lets the effects idle, and the
// last hit's pulse and number fade as they do while driving. At 0 the bar is the bare trough, and
// while the pulse shows, the bar's text is written over it, in the light text colour.
TEST(Effects, AfterTheLastHitTheBarEmptiesAndTheNumberFades) {
  Scene scene = sceneWith({parkedCar("A", 12.0, 0.0, 90.0)});
  scene.player.health = 3;
  World world(std::move(scene));
  Effects fx(world);
  driveIntoCar(world, fx);
  ASSERT_TRUE(world.gameOver());
  ASSERT_EQ(world.health(), 0);
  Camera camera;
  camera.center = world.car().position;
  camera.pixels_per_metre = 20.0;
  DrawOptions options;
  options.effects = &fx;
  const HealthBarRect bar = healthBarRect(camera.viewport);
  // Fills that lie inside the bar: the trough, plus the pulse's lost part while it shows.
  const auto inBar = [&](const RecordingCanvas& c) {
    std::vector<RecordingCanvas::Fill> out;
    const Eigen::Vector2f lo = bar.top_left - Eigen::Vector2f{0.5f, 0.5f};
    const Eigen::Vector2f hi = bar.top_left + bar.size + Eigen::Vector2f{0.5f, 0.5f};
    for (const RecordingCanvas::Fill& f : c.fills) {
      bool inside = true;
      for (const Eigen::Vector2f& p : f.points) {
        inside = inside && (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
      }
      if (inside) out.push_back(f);
    }
    return out;
  };
  const std::string number = "-" + std::to_string(world.hits()[0].damage);
  RecordingCanvas canvas(camera.viewport);
  drawFrame(canvas, world, camera, world.carBox(), options);
  EXPECT_TRUE(canvas.hasText(number));
  ASSERT_EQ(inBar(canvas).size(), 2u);  // trough and the health just lost
  const RecordingCanvas::Text* label = canvas.lastText("0 / 3");
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->color, (Rgba{235, 238, 242}));
  for (const RecordingCanvas::Fill& f : inBar(canvas)) EXPECT_LT(f.order, label->order);

  fx.idle(fx.settings().number_frames);
  EXPECT_EQ(fx.healthPulse(), 0.0f);
  EXPECT_EQ(fx.playerFlash(), 0.0f);
  EXPECT_EQ(fx.shake(), Eigen::Vector2f::Zero());
  drawFrame(canvas, world, camera, world.carBox(), options);
  EXPECT_FALSE(canvas.hasText(number));
  const std::vector<RecordingCanvas::Fill> left = inBar(canvas);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NEAR(left[0].width(), bar.size.x(), 1e-3f);  // the empty trough only
  EXPECT_TRUE(canvas.hasText("0 / 3"));
}

TEST(Effects, ParkedColoursAreStableAndVaried) {
  EXPECT_EQ(parkedColor("E1"), parkedColor("E1"));
  // FNV-1a of "a" is 0xe40c292c: fixed across runs and compilers.
  EXPECT_EQ(parkedColor("a"), Palette{}.car_colors[0xe40c292cu % 10u]);
  std::set<std::tuple<int, int, int>> seen;
  for (int i = 0; i < 40; ++i) {
    const Rgba c = parkedColor("P" + std::to_string(i));
    seen.insert({c.r, c.g, c.b});
  }
  EXPECT_GE(seen.size(), 7u);
}

}  // namespace
}  // namespace cardemo
