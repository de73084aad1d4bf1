#!/usr/bin/env bash
# WebAssembly against native (docs/performance.md): a headless replay's frames per second, native,
# `node cardemo.js` and in the page in headless chromium (tests/web/page-bench.js), on the same
# replay: circling.replay's input (throttle and full left lock in the open arena) held for FRAMES
# frames, long enough for about 1.5 s of native CPU. CPU time (user + system; the page's main
# thread), the median of RUNS runs, less the median of a 1-frame replay's (process start, wasm
# compile, scene). Then the page's frame time (update + draw) watching demo.replay (the parking lot)
# and large-lot.replay (10,100 parked cars). scripts/web.sh builds what it needs.
#
# Usage: scripts/web-bench.sh NATIVE_CARDEMO [WEB_BUILD_DIR] [RUNS]   (defaults: build-web, 5)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: scripts/web-bench.sh NATIVE_CARDEMO [WEB_BUILD_DIR] [RUNS]" >&2; exit 2; }
native=$(realpath "$1")
build=$(realpath "${2:-$root/build-web}")
runs=${3:-5}
frames=10000000
"$root/scripts/ensure-packages.sh" time
cd "$build/site"
# The replays, beside the page so that it can fetch them; paths relative to build/site.
mkdir -p bench
for n in "$frames" 1; do
  printf 'cardemo-replay 1\nscene ../assets/scenes/arena.json\nhz 120\n%d UL\n' "$n" >"bench/circling-$n.replay"
done
long=bench/circling-$frames.replay
one=bench/circling-1.replay

# cpu CMD...: user+system CPU seconds of one run.
times=$(mktemp)
cpu() {
  /usr/bin/time -o "$times" -f '%U %S' "$@" >/dev/null 2>&1
  awk '{ print $1 + $2 }' "$times"
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
# Interleaved, so that every kind of run sees the same load on the shared machine.
n=() n1=() w=() w1=()
for _ in $(seq "$runs"); do
  n1+=("$(cpu "$native" replay "$one")")
  n+=("$(cpu "$native" replay "$long")")
  w1+=("$(cpu node "$build/cardemo.js" replay "$one")")
  w+=("$(cpu node "$build/cardemo.js" replay "$long")")
done
echo "native CPU s: ${n[*]} (1 frame: ${n1[*]})"
echo "node CPU s: ${w[*]} (1 frame: ${w1[*]})"
awk -v n="$(median "${n[@]}")" -v n1="$(median "${n1[@]}")" -v w="$(median "${w[@]}")" \
  -v w1="$(median "${w1[@]}")" -v f="$frames" -v runs="$runs" 'BEGIN {
  printf "native %s: %.2f M frames/s (%.2f s CPU, less %.2f s load, median of %d)\n",
         ARGV[1], f / (n - n1) / 1e6, n, n1, runs
  printf "node cardemo.js: %.2f M frames/s (%.2f s CPU, less %.2f s load), %.2fx native\n",
         f / (w - w1) / 1e6, w, w1, (n - n1) / (w - w1)
}' "$long"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -f "$times"' EXIT
sleep 1
NODE_PATH="$build/npm/node_modules" node "$root/tests/web/page-bench.js" "http://127.0.0.1:$port" \
  "$runs" "$long" "$one" assets/replays/demo.replay assets/replays/large-lot.replay
