#!/usr/bin/env bash
# Builds cardemo and starts the game: the scene picker (parking levels and the free-drive lot).
# With a display: the SDL2 window (arrow keys drive, F1 lists every key). Without one: the bundled
# demo drive is replayed headless, its summary printed, and one frame is drawn to a PNG.
# Extra arguments go to `cardemo play` (e.g. a SCENE file, --record drive.replay).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
# shellcheck source=scripts/lib.sh
. "$root/scripts/lib.sh"
build="${CARDEMO_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_BUILD_TESTS=OFF \
  "${cardemo_launcher[@]}" >/dev/null
cmake --build "$build" --target cardemo -j"$(nproc)"
# The binary finds the bundled scenes, sounds and font next to itself only in a build folder inside
# the repository; this one may be anywhere (CARDEMO_BUILD_DIR).
export CARDEMO_ASSETS="${CARDEMO_ASSETS:-$root/assets}"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$build/cardemo" play "$@"
fi
echo "No display: replaying the demo drive headless instead of opening the window."
"$build/cardemo" replay "$root/assets/replays/demo.replay"
picture="$build/demo-frame.png"
"$build/cardemo" render "$root/assets/replays/demo.replay" --frame 1190 --debug --out "$picture"
