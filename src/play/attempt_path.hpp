#pragma once
/// Where each attempt of one game is recorded: restarting never overwrites an earlier attempt.

#include <string>

namespace cardemo {

/// The recording path of attempt `attempt` (1-based) of a game recorded with `--record base`:
/// `base` itself for the first attempt, then the number before the extension (`drive.replay`,
/// `drive-2.replay`, `drive-3.replay`, ...; `out/drive` gives `out/drive-2`). Only the last path
/// component's last extension moves (`a.b/run.x.replay` gives `a.b/run.x-2.replay`); a leading dot
/// is part of the name, not an extension (`.replay` gives `.replay-2`).
[[nodiscard]] std::string attemptPath(const std::string& base, int attempt);

}  // namespace cardemo
