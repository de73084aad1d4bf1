#!/usr/bin/env bash
# WebAssembly against native (docs/performance.md): the headless replay's frames per second, native
# and `node cardemo.js` (CPU time, best of RUNS, on assets/replays/circling.replay, 400,000 frames),
# then the page in headless chromium (tests/web/page-bench.js): the same replay run to its end,
# and the frame time (update + draw) watching demo.replay (the parking lot) and large-lot.replay
# (10,100 parked cars). scripts/web.sh builds what it needs.
#
# Usage: scripts/web-bench.sh NATIVE_CARDEMO [WEB_BUILD_DIR] [RUNS]   (defaults: build-web, 3)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: scripts/web-bench.sh NATIVE_CARDEMO [WEB_BUILD_DIR] [RUNS]" >&2; exit 2; }
native=$(realpath "$1")
build=$(realpath "${2:-$root/build-web}")
runs=${3:-3}
replay=assets/replays/circling.replay
frames=400000
"$root/scripts/ensure-packages.sh" time
cd "$build/site"
# best_cpu CMD...: the least user+system CPU seconds of RUNS runs.
times=$(mktemp)
best_cpu() {
  local best="" t
  for _ in $(seq "$runs"); do
    /usr/bin/time -o "$times" -f '%U %S' "$@" >/dev/null 2>&1
    t=$(awk '{ print $1 + $2 }' "$times")
    best=$(awk -v a="$t" -v b="${best:-$t}" 'BEGIN { print (a < b ? a : b) }')
  done
  echo "$best"
}
# The load (process start, wasm compile, scene) is a 1-frame replay's, subtracted.
one="$build/bench-one-frame.replay"
printf 'cardemo-replay 1\nscene %s\n1 .\n' "$build/site/$(dirname "$replay")/$(sed -n 's/^scene //p' "$replay")" >"$one"
n=$(best_cpu "$native" replay "$replay")
n1=$(best_cpu "$native" replay "$one")
w=$(best_cpu node "$build/cardemo.js" replay "$replay")
w1=$(best_cpu node "$build/cardemo.js" replay "$one")
awk -v n="$n" -v n1="$n1" -v w="$w" -v w1="$w1" -v f="$frames" 'BEGIN {
  printf "native %s: %.2f M frames/s (%.2f s CPU, less %.2f s load)\n", ARGV[1], f / (n - n1) / 1e6, n, n1
  printf "node cardemo.js: %.2f M frames/s (%.2f s CPU, less %.2f s load), %.2fx native\n",
         f / (w - w1) / 1e6, w, w1, (n - n1) / (w - w1)
}' "$replay"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -f "$times"' EXIT
sleep 1
NODE_PATH="$build/npm/node_modules" node "$root/tests/web/page-bench.js" "http://127.0.0.1:$port" \
  "$replay" assets/replays/demo.replay assets/replays/large-lot.replay
