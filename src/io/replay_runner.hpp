#pragma once
/// Running a replay's inputs through a World, and checking its expectations.

#include <functional>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/replay_text.hpp"
#include "sim/bay_chain.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Loads the scene a replay names (`scene_override`, the --scene option, wins when non-empty). A
/// replay without a scene and without an override is an error on the replay's line 1; a scene file
/// that cannot be read is reported where it was named (see loadSceneOfReplay, loadSceneOption).
[[nodiscard]] Parsed<Scene> loadReplayScene(const Replay& replay, const std::string& replay_path,
                                            const std::string& scene_override);

/// Loads the scene on the replay's `scene` line; an unreadable file is reported on that line:
/// `REPLAY:LINE: scene PATH: cannot open: ...` (errors inside the scene keep the scene's line).
[[nodiscard]] Parsed<Scene> loadSceneOfReplay(const Replay& replay, const std::string& replay_path);

/// Loads a scene given by a command-line option; an unreadable file is reported as
/// `OPTION PATH: cannot open: ...` (errors inside the scene keep the scene's line).
[[nodiscard]] Parsed<Scene> loadSceneOption(const std::string& option, const std::string& path);

/// World settings for a replay (its `hz`, everything else default).
[[nodiscard]] WorldSettings settingsForReplay(const Replay& replay);

/// Steps `world` through every input frame of `replay`, calling `after_step` (when set) after each.
void runReplayInputs(World& world, const Replay& replay,
                     const std::function<void(const World&)>& after_step = {});

/// A parking challenge for the world's scene that has observed its current frame, or nullopt when
/// the scene has no goal.
[[nodiscard]] std::optional<ParkingChallenge> startChallenge(const World& world);

/// Free drive's bay chain over the world's scene, having observed its current frame.
[[nodiscard]] BayChain startBayChain(const World& world);

/// Compares the replay's expectation lines with the world's outcome (and the challenge's, for
/// `expect parked`; null when the scene has no goal); one sentence per difference.
[[nodiscard]] std::vector<std::string> checkExpectations(
    const Replay& replay, const World& world, const ParkingChallenge* challenge = nullptr);

/// Expectation lines that describe the world's outcome exactly (for `replay --print-expect`); with
/// a challenge, also `expect parked`.
[[nodiscard]] ReplayExpectations expectationsOf(const World& world,
                                                const ParkingChallenge* challenge = nullptr);

}  // namespace cardemo
