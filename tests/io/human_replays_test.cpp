// Every level ships a golden replay at a person's tempo, assets/replays/LEVEL.human.replay
// (scripts/make_human_replays.py): each input line holds its keys for at least 30 frames (0.25 s
// at 120 Hz), the drive parks, and the level's par is its parked time rounded up to whole seconds
// (scripts/make_levels.py reads it from there). The replays' hashes are checked as golden tests.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "io/replay_runner.hpp"
#include "io/scene_json.hpp"

namespace cardemo::human_replays_test {
namespace {

// The shortest a person holds or releases keys: 0.25 s.
constexpr double kShortestHoldSeconds = 0.25;

TEST(HumanReplays, EveryLevelHasOneAtAPersonsTempoThatParksAndSetsThePar) {
  const std::filesystem::path assets = std::filesystem::path(CARDEMO_SOURCE_DIR) / "assets";
  int levels = 0;
  for (const auto& entry : std::filesystem::directory_iterator(assets / "scenes/levels")) {
    if (entry.path().extension() != ".json") continue;
    ++levels;
    const std::string name = entry.path().stem().string();
    const std::filesystem::path path = assets / "replays" / (name + ".human.replay");
    ASSERT_TRUE(std::filesystem::exists(path)) << name << ": no " << path;
    const Parsed<Replay> replay = loadReplay(path.string());
    ASSERT_TRUE(replay.ok()) << replay.error().toString();
    const Parsed<Scene> scene = loadReplayScene(replay.value(), path.string(), "");
    ASSERT_TRUE(scene.ok()) << scene.error().toString();
    ASSERT_TRUE(scene.value().goal.has_value()) << name;
    EXPECT_EQ(scene.value().name, name) << "the human replay drives its own level";

    const auto shortest =
        static_cast<std::int64_t>(std::ceil(kShortestHoldSeconds * replay.value().hz));
    ASSERT_FALSE(replay.value().runs.empty()) << name;
    for (std::size_t i = 0; i < replay.value().runs.size(); ++i) {
      EXPECT_GE(replay.value().runs[i].count, shortest) << name << ": input line " << i + 1;
    }

    World world(scene.value(), settingsForReplay(replay.value()));
    std::optional<ParkingChallenge> challenge = startChallenge(world);
    runReplayInputs(world, replay.value(), [&](const World& w) { challenge->observe(w); });
    ASSERT_TRUE(challenge->score().has_value()) << name << ": the human replay does not park";
    const ParkingScore score = *challenge->score();
    EXPECT_EQ(score.damage, 0) << name;
    ASSERT_TRUE(scene.value().goal->par_time.has_value()) << name;
    const double par = *scene.value().goal->par_time;
    const double rounded_up = std::ceil(score.seconds);
    EXPECT_EQ(par, rounded_up) << name << ": the par is the human replay's " << score.seconds
                               << " s rounded up";
    EXPECT_EQ(score.stars, kMaxStars) << name;
  }
  EXPECT_EQ(levels, 10);
}

}  // namespace
}  // namespace cardemo::human_replays_test
