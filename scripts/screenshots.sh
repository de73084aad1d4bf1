#!/usr/bin/env bash
# Regenerates the screenshots in docs/img/ with `cardemo render` (headless: no window, no display).
# Usage: scripts/screenshots.sh   (CARDEMO_BUILD_DIR picks the build folder; default ./build)
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${CARDEMO_BUILD_DIR:-$root/build}"
out="$root/docs/img"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build" --target cardemo
bin="$build/cardemo"
if ! "$bin" render --help >/dev/null 2>&1; then
  echo "screenshots.sh: $bin has no render command (built without SDL2? install libsdl2-dev," \
    "libsdl2-image-dev, libsdl2-ttf-dev)" >&2
  exit 2
fi
mkdir -p "$out"

shot() {  # shot NAME INPUT [render options...]
  local name="$1" input="$2"
  shift 2
  env -u DISPLAY -u WAYLAND_DISPLAY "$bin" render "$root/$input" --width 1280 --height 720 "$@" \
    --out "$out/$name.png"
}

shot parking-lot assets/scenes/parking-lot.json --center 0 0 --zoom 8.5 --sprites
shot level assets/replays/level-3-parallel.replay --frame 200 --rig --sprites
shot crash assets/replays/head-on.replay --frame 866 --rig --zoom 30 --sprites
shot demo assets/replays/demo.replay --frame 330 --zoom 18 --rig
shot demo-debug assets/replays/demo.replay --frame 1190 --zoom 24 --debug --rig
shot garage assets/replays/garage.replay --frame 300 --zoom 26 --rig --sprites
shot slalom assets/replays/level-5-slalom.replay --frame 420 --rig --sprites
shot help assets/scenes/garage.json --zoom 26 --help-panel --rig
