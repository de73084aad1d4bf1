#pragma once
/// The one-line status under the HUD in a level.

#include <string>

#include "play/game_session.hpp"

namespace cardemo {

/// `note` (the last thing said: "attempt 2", "sound off", where a screenshot went), then, while
/// the run goes on, "replaying REPLAY_PATH (N frames left)" and "recording to FILE"; once it has
/// ended nothing is replayed or recorded any more, and the line says "recorded to FILE" instead
/// (unless the recording failed). Parts are two spaces apart.
[[nodiscard]] std::string statusLine(const GameSession& session, const std::string& replay_path,
                                     const std::string& note, bool ended);

}  // namespace cardemo
