// SoundMix: engine cross-fade by speed, screech from the car's motion, impacts from hits.

#include "play/sound_mix.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/scene_json.hpp"

namespace cardemo {
namespace {

const std::string kLotScene = std::string(CARDEMO_SOURCE_DIR) + "/assets/scenes/parking-lot.json";

World lot(int health = 100) {
  Parsed<Scene> scene = loadScene(kLotScene);
  EXPECT_TRUE(scene.ok());
  Scene s = std::move(scene).value();
  s.player.health = health;
  return World(std::move(s));
}

TEST(EngineGains, EndsPlayOneLoopAlone) {
  const auto idle = engineGains(0.0);
  EXPECT_EQ(idle[0], 1.0);
  for (std::size_t i = 1; i < kEngineLoops; ++i) EXPECT_EQ(idle[i], 0.0);
  const auto top = engineGains(SoundSettings{}.top_speed * 2.0);
  EXPECT_NEAR(top[kEngineLoops - 1], 1.0, 1e-12);
  for (std::size_t i = 0; i + 1 < kEngineLoops; ++i) EXPECT_NEAR(top[i], 0.0, 1e-12);
  EXPECT_EQ(engineGains(-5.0), engineGains(5.0));  // reversing sounds like driving
}

TEST(EngineGains, EqualPowerAndPitchRisesWithSpeed) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> speed(0.0, 50.0);
  for (int i = 0; i < 1000; ++i) {
    const auto g = engineGains(speed(rng));
    double power = 0.0;
    int audible = 0;
    for (double x : g) {
      EXPECT_GE(x, 0.0);
      power += x * x;
      audible += x > 1e-12 ? 1 : 0;
    }
    EXPECT_NEAR(power, 1.0, 1e-12);
    EXPECT_LE(audible, 2);
  }
  // The gain-weighted loop index (the heard pitch) never falls as the speed rises.
  double last = -1.0;
  for (double v = 0.0; v <= 45.0; v += 0.25) {
    const auto g = engineGains(v);
    double centre = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < kEngineLoops; ++i) {
      centre += static_cast<double>(i) * g[i] * g[i];
      sum += g[i] * g[i];
    }
    EXPECT_GE(centre / sum, last - 1e-12) << v;
    last = centre / sum;
  }
}

TEST(ScreechLevel, StraightIsSilentHardCornerAndBrakingSqueal) {
  const CarParams params;
  CarState car;
  car.speed = 30.0;
  EXPECT_EQ(screechLevel(car, params, {}), 0.0);
  car.steer = 0.3;  // 900 * tan(0.3) / 2.7 = 103 m/s^2: far past full
  EXPECT_EQ(screechLevel(car, params, {}), 1.0);
  car.speed = 3.0;  // 9 * 0.309 / 2.7 = 1.03 m/s^2: below the threshold
  EXPECT_EQ(screechLevel(car, params, {}), 0.0);
  // Exactly between threshold and full: v^2 tan(s) / L = 9.
  const SoundSettings s;
  car.steer = 0.2;
  car.speed = std::sqrt(9.0 * params.wheelbase / std::tan(0.2));
  EXPECT_NEAR(screechLevel(car, params, {}, s),
              (9.0 - s.slide_accel) / (s.slide_full_accel - s.slide_accel), 1e-9);
  CarState braking;
  braking.speed = 20.0;
  const InputFrame down{false, true, false, false};
  EXPECT_GT(screechLevel(braking, params, down), 0.0);
  braking.speed = 5.0;
  EXPECT_EQ(screechLevel(braking, params, down), 0.0);
  braking.speed = -20.0;  // Down while reversing is the throttle backwards, not a brake
  EXPECT_EQ(screechLevel(braking, params, down), 0.0);
}

TEST(SoundMix, HitsSoundOnceWithLevelFollowingDamage) {
  World world = lot();
  SoundMix mix;
  const InputFrame up{true, false, false, false};
  std::vector<double> impacts;
  for (int i = 0; i < 1500; ++i) {
    world.step(up);
    const SoundFrame f = mix.update(world, up, false);
    if (f.impact > 0.0) impacts.push_back(f.impact);
  }
  ASSERT_FALSE(world.hits().empty());
  ASSERT_EQ(impacts.size(), world.hits().size());
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    EXPECT_DOUBLE_EQ(impacts[i], std::clamp(world.hits()[i].damage / 50.0,
                                            SoundSettings{}.min_impact_level, 1.0));
  }
}

TEST(SoundMix, EngineFollowsSpeedAndStopsWhenHoldingOrOver) {
  World world = lot();
  SoundMix mix;
  const SoundFrame idle = mix.update(world, {}, false);
  EXPECT_NEAR(idle.engine[0], SoundSettings{}.idle_level, 1e-12);
  const InputFrame up{true, false, false, false};
  for (int i = 0; i < 500; ++i) world.step(up);
  const SoundFrame fast = mix.update(world, up, false);
  EXPECT_GT(fast.engine[1] + fast.engine[2], 0.0);
  const SoundFrame held = mix.update(world, up, true);
  for (double g : held.engine) EXPECT_EQ(g, 0.0);

  World over = lot(1);
  SoundMix over_mix;
  for (int i = 0; i < 3000 && !over.gameOver(); ++i) over.step(up);
  ASSERT_TRUE(over.gameOver());
  const SoundFrame end = over_mix.update(over, up, false);
  EXPECT_GT(end.impact, 0.0);  // the final crash is heard
  for (double g : end.engine) EXPECT_EQ(g, 0.0);
  EXPECT_EQ(end.screech, 0.0);
}

TEST(SoundMix, ARestartedGameIsHeardAfresh) {
  const InputFrame up{true, false, false, false};
  World first = lot(1);
  SoundMix mix;
  for (int i = 0; i < 3000 && !first.gameOver(); ++i) first.step(up);
  EXPECT_GT(mix.update(first, up, false).impact, 0.0);
  EXPECT_EQ(mix.update(first, up, false).impact, 0.0);  // not twice
  World second = lot(1);
  EXPECT_EQ(mix.update(second, {}, false).impact, 0.0);
  for (int i = 0; i < 3000 && !second.gameOver(); ++i) second.step(up);
  EXPECT_GT(mix.update(second, up, false).impact, 0.0);
}

TEST(SoundMix, HandbrakeSlideScreeches) {
  World world = lot();
  SoundMix mix;
  const InputFrame up{true, false, false, false};
  for (int i = 0; i < 360; ++i) world.step(up);  // about 3 s of throttle, well above skid_slip
  EXPECT_EQ(mix.update(world, up, false).screech, 0.0);
  const InputFrame handbrake{false, false, false, false, true};
  world.step(handbrake);
  ASSERT_TRUE(world.sliding());
  EXPECT_GE(mix.update(world, handbrake, false).screech, SoundSettings{}.min_slide_level);
}

}  // namespace
}  // namespace cardemo
