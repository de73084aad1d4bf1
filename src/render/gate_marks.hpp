#pragma once
/// A goal's gates on the ground: passed ones green with a tick, the next one bright, the rest
/// dim, each numbered; and the words of a fresh miss for the timer panel.

#include <optional>
#include <string>

#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "sim/parking_goal.hpp"

namespace cardemo {

/// Seconds a missed gate's message (or a wrong-way crossing's) stays on screen.
inline constexpr double kGateNoticeSeconds = 3.0;

/// The gates of `challenge`'s goal, painted on the ground (under the cars).
void drawGates(Canvas& canvas, const Camera& camera, const ParkingChallenge& challenge);

/// The message of a miss or a wrong-way crossing made in the last kGateNoticeSeconds, while the
/// run goes on ("missed gate 2: NAME"), else nothing.
[[nodiscard]] std::optional<std::string> freshGateWarning(const ParkingChallenge& challenge);

}  // namespace cardemo
