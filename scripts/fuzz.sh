#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan+UBSan) and runs each for SECONDS (default 60; CI runs
# 20, see scripts/test.sh), two at a time, from its committed seed corpus (fuzz/corpus/NAME) with its
# dictionary (fuzz/dict/NAME.dict).
#   scripts/fuzz.sh [SECONDS] [TARGET...]      TARGET: scene_json replay_text pair_csv sat2 sat3
# New corpus entries go to BUILD/fuzz-work/NAME (never into the repository); crashes, leaks, hangs
# and failed properties are saved as BUILD/fuzz-crashes/NAME-*, and the script then exits 1.
# Prints the executions reached per target. Environment:
#   CARDEMO_FUZZ_BUILD_DIR  build folder (default build-fuzz); reused as is when it already has
#                           CARDEMO_FUZZ=ON (scripts/ci-sanitize.sh passes its own)
#   CARDEMO_FUZZ_JOBS       targets run at once (default 2)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for source in "$root"/fuzz/*.cpp; do targets+=("$(basename "$source" .cpp)"); done
fi
build="${CARDEMO_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs=${CARDEMO_FUZZ_JOBS:-2}

if ! grep -q '^CARDEMO_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  # shellcheck source=scripts/lib.sh
  . "$root/scripts/lib.sh"
  CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_FUZZ=ON \
    -DCARDEMO_BUILD_TESTS=OFF -DCARDEMO_BUILD_BENCH=OFF -DCARDEMO_WITH_SDL=OFF -DCARDEMO_WITH_BOX2D=OFF \
    "${cardemo_launcher[@]}" >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

crashes="$build/fuzz-crashes"
mkdir -p "$crashes"
# Runs one target; its log is BUILD/fuzz-work/NAME.log.
run_one() {
  local name=$1 work="$build/fuzz-work/$name" args=()
  mkdir -p "$work/corpus"
  [ -f "$root/fuzz/dict/$name.dict" ] && args+=("-dict=$root/fuzz/dict/$name.dict")
  case $name in sat*) args+=(-max_len=512) ;; *) args+=(-max_len=8192) ;; esac
  "$build/fuzz/fuzz_$name" "${args[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$crashes/$name-" \
    "$work/corpus" "$root/fuzz/corpus/$name" >"$work.log" 2>&1
}

status=0
pids=() names=()
for name in "${targets[@]}"; do
  [ -x "$build/fuzz/fuzz_$name" ] || { echo "no fuzz target $name" >&2; exit 2; }
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  echo "fuzz_$name: running for $seconds s"
  run_one "$name" &
  pids+=($!) names+=("$name")
done
failed=()
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failed+=("${names[$i]}")
done

printf '%-12s %14s %10s %8s  %s\n' target executions exec/s corpus result
for name in "${targets[@]}"; do
  log="$build/fuzz-work/$name.log"
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  corpus=$(find "$build/fuzz-work/$name/corpus" -type f | wc -l)
  result=ok
  if [[ " ${failed[*]} " == *" $name "* ]]; then result="FAILED (see $log)"; status=1; fi
  printf '%-12s %14s %10s %8s  %s\n' "$name" "${execs:-?}" "${rate:-?}" "$corpus" "$result"
done
if [ "$status" -ne 0 ]; then
  for name in "${failed[@]}"; do
    echo "--- fuzz_$name:" >&2
    grep -E -m 20 'fuzz property failed|ERROR: |SUMMARY: |runtime error|^  ' "$build/fuzz-work/$name.log" >&2 || tail -30 "$build/fuzz-work/$name.log" >&2
  done
  echo "crash inputs: $crashes (rerun one with: $build/fuzz/fuzz_NAME FILE)" >&2
fi
exit "$status"
