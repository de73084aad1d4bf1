#include "io/replay_runner.hpp"

#include <cstdio>

#include "io/scene_json.hpp"

namespace cardemo {

namespace {

// `path` loaded; an error about the file as a whole (line 0: missing, unreadable, too large) is
// moved to `where`, with `named` (how the referrer wrote the path, if not already in `where`)
// before its message.
Parsed<Scene> loadSceneReferenced(const std::string& path, InputError where,
                                  const std::string& named) {
  Parsed<Scene> scene = loadScene(path);
  if (scene.ok() || scene.error().line != 0 || scene.error().file != path) return scene;
  where.message = named.empty() ? scene.error().message : named + ": " + scene.error().message;
  return where;
}

}  // namespace

Parsed<Scene> loadSceneOfReplay(const Replay& replay, const std::string& replay_path) {
  return loadSceneReferenced(replay.scene_resolved, InputError{replay_path, replay.scene_line, ""},
                             "scene " + replay.scene);
}

Parsed<Scene> loadSceneOption(const std::string& option, const std::string& path) {
  // No line: the file part is the option itself, so the message reads `--scene PATH: ...`.
  return loadSceneReferenced(path, InputError{option + " " + path, 0, ""}, "");
}

Parsed<Scene> loadReplayScene(const Replay& replay, const std::string& replay_path,
                              const std::string& scene_override) {
  if (!scene_override.empty()) return loadSceneOption("--scene", scene_override);
  if (replay.scene_resolved.empty()) {
    return InputError{replay_path, 1,
                      "the replay names no scene: add a `scene PATH` line or pass --scene"};
  }
  return loadSceneOfReplay(replay, replay_path);
}

WorldSettings settingsForReplay(const Replay& replay) {
  WorldSettings settings;
  settings.hz = replay.hz;
  return settings;
}

void runReplayInputs(World& world, const Replay& replay,
                     const std::function<void(const World&)>& after_step) {
  if (!after_step) {
    for (const InputRun& run : replay.runs) {
      for (std::int64_t i = 0; i < run.count; ++i) world.step(run.keys);
    }
    return;
  }
  for (const InputRun& run : replay.runs) {
    for (std::int64_t i = 0; i < run.count; ++i) {
      world.step(run.keys);
      after_step(world);
    }
  }
}

namespace {

std::string hitsText(const std::vector<ExpectedHit>& hits) {
  if (hits.empty()) return "none";
  std::string out;
  for (const ExpectedHit& h : hits) {
    if (!out.empty()) out += ", ";
    out += std::to_string(h.frame) + " " + h.id;
  }
  return out;
}

}  // namespace

std::optional<ParkingChallenge> startChallenge(const World& world) {
  const Scene& scene = world.scene();
  if (!scene.goal) return std::nullopt;
  std::optional<ParkingChallenge> challenge(std::in_place, *scene.goal, world.settings().hz,
                                            scene.player.health);
  challenge->observe(world);
  return challenge;
}

BayChain startBayChain(const World& world) {
  BayChain chain(world.scene(), world.settings().hz);
  chain.observe(world);
  return chain;
}

ReplayExpectations expectationsOf(const World& world, const ParkingChallenge* challenge) {
  ReplayExpectations e;
  e.frames = world.frame();
  e.health = world.health();
  e.hit_count = static_cast<std::int64_t>(world.hits().size());
  std::vector<ExpectedHit> hits;
  for (const HitEvent& h : world.hits()) hits.push_back({h.frame, h.id});
  e.hits = std::move(hits);
  e.hash = hashHex(world.stateHash());
  if (challenge != nullptr) e.parked = challenge->parkedFrame();
  return e;
}

std::vector<std::string> checkExpectations(const Replay& replay, const World& world,
                                           const ParkingChallenge* challenge) {
  std::vector<std::string> diffs;
  const ReplayExpectations actual = expectationsOf(world, challenge);
  const ReplayExpectations& want = replay.expect;
  if (want.frames && *want.frames != *actual.frames) {
    diffs.push_back("frames: expected " + std::to_string(*want.frames) + ", got " +
                    std::to_string(*actual.frames));
  }
  if (want.health && *want.health != *actual.health) {
    diffs.push_back("health: expected " + std::to_string(*want.health) + ", got " +
                    std::to_string(*actual.health));
  }
  if (want.hit_count && *want.hit_count != *actual.hit_count) {
    diffs.push_back("hits: expected " + std::to_string(*want.hit_count) + ", got " +
                    std::to_string(*actual.hit_count));
  }
  if (want.hits) {
    const auto& w = *want.hits;
    const auto& a = *actual.hits;
    bool same = w.size() == a.size();
    for (std::size_t i = 0; same && i < w.size(); ++i)
      same = w[i].frame == a[i].frame && w[i].id == a[i].id;
    if (!same)
      diffs.push_back("hit list: expected [" + hitsText(w) + "], got [" + hitsText(a) + "]");
  }
  if (want.hash && *want.hash != *actual.hash) {
    diffs.push_back("hash: expected " + *want.hash + ", got " + *actual.hash);
  }
  if (want.parked) {
    const auto text = [](const std::optional<std::int64_t>& f) {
      return f ? "frame " + std::to_string(*f) : std::string("never");
    };
    if (!actual.parked) {
      diffs.push_back("parked: expected " + text(*want.parked) + ", but the scene has no goal");
    } else if (*want.parked != *actual.parked) {
      diffs.push_back("parked: expected " + text(*want.parked) + ", got " + text(*actual.parked));
    }
  }
  return diffs;
}

}  // namespace cardemo
