#pragma once
/// SIGINT, SIGTERM and SIGHUP end `cardemo play` cleanly: the handlers only record the signal, and
/// the picker and game loops stop when they see it.

namespace cardemo {

/// Installs the handlers; later calls do nothing.
void installStopSignals();

/// The signal that asked the game to stop, or 0.
[[nodiscard]] int stopSignal();

}  // namespace cardemo
