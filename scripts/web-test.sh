#!/usr/bin/env bash
# The browser build's command line against a native cardemo. Each check runs one command twice,
# as `node cardemo.js ARGS` and as `NATIVE ARGS`, each in an empty folder of its own with the same
# stdin, and requires the same stdout, stderr, exit status and files written, byte for byte:
#   - every golden replay in assets/replays: the summary (exit 0: its expectations, hash included,
#     are met), --json - and --trace FILE in one run, and --print-expect;
#   - bad input: a malformed replay, scenes with bad JSON, an unknown key, a number out of range
#     and deep nesting, a missing file, usage errors: one `FILE:LINE: ...` line, exit 2;
#   - collide: assets/pairs (2D and 3D, from a file and from stdin), seeded random rows with
#     numbers in many notations (tiny, huge, subnormal sizes), a malformed CSV.
# Then the web build alone: compare and render say they are not in this build (exit 2) and --help
# lists neither.
#
# Usage: scripts/web-test.sh NATIVE_CARDEMO [CARDEMO_JS]   (default: build-web/cardemo.js)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: scripts/web-test.sh NATIVE_CARDEMO [CARDEMO_JS]" >&2; exit 2; }
native=$(realpath "$1")
web=$(realpath "${2:-$root/build-web/cardemo.js}")
[ -x "$native" ] || { echo "web-test: no native cardemo at $1" >&2; exit 2; }
[ -f "$web" ] || { echo "web-test: no $web (scripts/web.sh builds it)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs="$work/inputs"
mkdir -p "$inputs"
parallel=$(nproc)
names=()          # the checks that compare the two builds
status_checks=()  # NAME:CODE, the web build's exit status
bad_checks=()     # NAMEs whose stderr must be one FILE:LINE line, exit 2
checks=0
failed=0

fail() {
  echo "web-test: $*" >&2
  failed=$((failed + 1))
}

# run SIDE NAME STDIN ARGS...: one build's run, in its own folder: stdout, stderr, status, files.
run() {
  local side=$1 name=$2 input=$3
  shift 3
  local dir="$work/$side/$name" code=0
  local cmd=("$native")
  [ "$side" = web ] && cmd=(node "$web")
  mkdir -p "$dir/files"
  (cd "$dir/files" && "${cmd[@]}" "$@" <"$input" >"$dir/stdout" 2>"$dir/stderr") || code=$?
  echo "$code" >"$dir/status"
}

# same NAME STDIN ARGS...: the command on both builds, compared once all have run; up to one
# check per core at a time.
same() {
  names+=("$1")
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  (run native "$@" && run web "$@") &
}

# status NAME CODE: the web build's exit status for check NAME must be CODE.
status() {
  status_checks+=("$1:$2")
}

# bad_input NAME: exit 2 with one `FILE:LINE: ...` line on stderr.
bad_input() {
  bad_checks+=("$1")
}

# Golden replays.
replays=()
for replay in "$root"/assets/replays/*.replay; do
  name=$(basename "$replay" .replay)
  replays+=("$name")
  # The summary (with its expectations) on stderr, the JSON on stdout, the trace in a file.
  same "replay.$name" /dev/null replay "$replay" --json - --trace trace.csv
  status "replay.$name" 0
  same "expect.$name" /dev/null replay "$replay" --print-expect
done

# Bad input.
scene="$root/assets/scenes/parking-lot.json"
printf 'cardemo-replay 1\nscene %s\n120 U\n10 UX\n' "$scene" >"$inputs/bad-keys.replay"
printf 'cardemo-replay 2\n' >"$inputs/bad-header.replay"
printf 'cardemo-replay 1\nscene %s\n120 U\n' "$scene" >"$inputs/ok.replay"
printf '{"format": "cardemo-scene/1", "name": "x",\n "player": {"x": 0, "y": 0,\n "parked": [ }\n' \
  >"$inputs/syntax.json"
sed 's/"parked"/"parkd"/' "$scene" >"$inputs/unknown-key.json"
sed '0,/"x": [-0-9.]*/s//"x": 1e999/' "$scene" >"$inputs/huge-number.json"
python3 -c 'print("[" * 100000 + "]" * 100000)' >"$inputs/deep.json"
same bad.keys /dev/null replay "$inputs/bad-keys.replay"
same bad.header /dev/null replay "$inputs/bad-header.replay"
same bad.missing /dev/null replay "$inputs/missing.replay"
for json in syntax unknown-key huge-number deep; do
  same "bad.scene-$json" /dev/null replay "$inputs/ok.replay" --scene "$inputs/$json.json"
done
for check in bad.keys bad.header bad.scene-syntax bad.scene-unknown-key bad.scene-huge-number \
  bad.scene-deep; do
  bad_input "$check"
done
status bad.missing 2
same usage.no-replay /dev/null replay
same usage.unknown /dev/null fly
same usage.bad-option /dev/null replay "$inputs/ok.replay" --hz 0
same version /dev/null --version
status usage.no-replay 2
status usage.unknown 2

# Pair queries.
same collide.2d /dev/null collide "$root/assets/pairs/boxes2.csv"
same collide.3d /dev/null collide "$root/assets/pairs/boxes3.csv" --dim 3
same collide.stdin "$root/assets/pairs/boxes2.csv" collide -
python3 - "$inputs" <<'EOF'
# Seeded random rows, each number in one of many notations that the reader accepts.
import random, sys
rng = random.Random(41)
def text(v):
    style = rng.randrange(9)
    if style in (4, 6) and abs(v) < 1e-3:
        style = 0  # fixed notation would write a tiny size as 0
    if style == 0: return repr(v)
    if style == 1: return "%.3e" % v
    if style == 2: return "%+g" % v
    if style == 3: return "%.17g" % v
    if style == 4: return "%.6f" % v
    if style == 5: return "%.*E" % (rng.randrange(20), v)
    if style == 6: return ("%.9f" % v).rstrip("0")  # "5." style
    if style == 7: return " %r " % v
    return "%.20g" % v
def coordinate():
    return rng.choice([rng.uniform(-10, 10), rng.uniform(-1e9, 1e9), rng.uniform(-1e-3, 1e-3),
                       1e7 + rng.uniform(-5, 5), float(rng.randrange(-100, 100))])
def size():
    return rng.choice([rng.uniform(0.01, 100), 10 ** rng.uniform(-300, 9), 5e-324, 2.2e-308,
                       rng.uniform(1, 5), 1e9])
def box2():
    return [coordinate(), coordinate(), rng.uniform(-720, 720), size(), size()]
def box3():
    return [coordinate(), coordinate(), coordinate()] + \
           [rng.uniform(-1, 1) for _ in range(4)] + [size(), size(), size()]
with open(sys.argv[1] + "/random2.csv", "w") as f:
    for _ in range(3000):
        a, b = box2(), box2()
        if rng.random() < 0.5:  # near each other, so that many touch
            b[0], b[1] = a[0] + rng.uniform(-5, 5), a[1] + rng.uniform(-5, 5)
        f.write(",".join(text(v) for v in a + b) + "\n")
with open(sys.argv[1] + "/random3.csv", "w") as f:
    for _ in range(3000):
        a, b = box3(), box3()
        if rng.random() < 0.5:
            b[0], b[1], b[2] = (a[i] + rng.uniform(-5, 5) for i in range(3))
        f.write(",".join(text(v) for v in a + b) + "\n")
EOF
same collide.random2 /dev/null collide "$inputs/random2.csv"
same collide.random3 /dev/null collide "$inputs/random3.csv" --dim 3
status collide.random2 0
status collide.random3 0
printf '0,0,0,4,2,3,1,90,4,2\n0,0,0,4,2,3,1,90,4,1e400\n' >"$inputs/bad.csv"
same collide.bad /dev/null collide "$inputs/bad.csv"
bad_input collide.bad

wait
for name in "${names[@]}"; do
  checks=$((checks + 1))
  if ! diff -r "$work/native/$name" "$work/web/$name" >"$work/diff" 2>&1; then
    fail "$name: node and native differ:"
    head -n 20 "$work/diff" >&2
  fi
done
for name in "${replays[@]}"; do
  checks=$((checks + 1))
  [ -s "$work/web/replay.$name/files/trace.csv" ] || fail "replay.$name: no trace written"
done
for check in "${status_checks[@]}"; do
  name=${check%:*} code=${check##*:}
  got=$(<"$work/web/$name/status")
  checks=$((checks + 1))
  [ "$got" = "$code" ] ||
    fail "$name: exit status $got, expected $code ($(head -c 300 "$work/web/$name/stderr"))"
done
for name in "${bad_checks[@]}"; do
  err="$work/web/$name/stderr"
  checks=$((checks + 1))
  if ! { [ "$(<"$work/web/$name/status")" = 2 ] && [ "$(wc -l <"$err")" -eq 1 ] &&
    grep -Eq '^[^:]+:[0-9]+: .' "$err"; }; then
    fail "$name: not exit 2 with one FILE:LINE line: $(head -c 300 "$err")"
  fi
done

# The web build alone: what it leaves out.
for sub in compare render play; do
  err=$(node "$web" "$sub" "$root/assets/replays/demo.replay" 2>&1 >/dev/null) && code=0 || code=$?
  checks=$((checks + 1))
  if [ "$code" -ne 2 ] || [[ "$err" != *"not available in this build"* ]]; then
    fail "$sub: expected 'not available in this build' and exit 2, got $code: $err"
  fi
done
help=$(node "$web" --help)
checks=$((checks + 1))
if grep -Eq '^  (compare|render|play)' <<<"$help" || ! grep -q '^  replay' <<<"$help"; then
  fail "--help lists commands this build does not have, or misses replay: $help"
fi

if [ "$failed" -ne 0 ]; then
  echo "web-test: $failed of $checks checks failed" >&2
  exit 1
fi
echo "web-test: $checks checks passed: node $web gives the native output"
