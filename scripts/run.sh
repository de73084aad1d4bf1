#!/usr/bin/env bash
# Builds cardemo and starts it on the bundled default scene.
# Until the window lands (issue 3), this replays the bundled demo drive headless and prints its summary.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
build="${CARDEMO_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target cardemo -j"$(nproc)"
exec "$build/cardemo" replay "$root/assets/replays/demo.replay" "$@"
