#!/usr/bin/env bash
# Determinism across builds: builds `cardemo` alone with each compiler and build type below, replays
# every golden replay in each, and prints the final state hash of each replay per build. It fails unless
# every build gives every replay's expected hash (the replays' `expect hash` lines), i.e. unless all
# builds agree bit for bit.
#
# Usage: scripts/check-determinism.sh [BUILD_ROOT]   (default: build-determinism/ in the repo)
# The RelWithDebInfo/GCC tree and the clang ASan+UBSan tree are checked by their own CTest runs
# (the golden.* tests), so together CI covers GCC and Clang x Debug, Release, RelWithDebInfo and
# the sanitizers.
#
# A replay needs neither the window (SDL) nor the Box2D comparison, so these trees leave both out:
# each compiles the core and the command line only.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out="${1:-$root/build-determinism}"
jobs=$(nproc)
# shellcheck source=scripts/lib.sh
. "$root/scripts/lib.sh"
stage_begin "determinism"
# CARDEMO_DETERMINISM_BUILDS narrows the list (CI leaves out clang:Release: its sanitizer tree, clang
# -O2, checks the same hashes in its golden.* tests).
read -r -a builds <<<"${CARDEMO_DETERMINISM_BUILDS:-gcc:Debug:g++ gcc:Release:g++ clang:Release:clang++}"

replays=("$root"/assets/replays/*.replay)
declare -A hashes
failed=0
for spec in "${builds[@]}"; do
  IFS=: read -r compiler type cxx <<<"$spec"
  dir="$out/$compiler-$type"
  # No debug information (-g changes no generated instruction, and it is a third of the compile).
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_CXX_FLAGS_DEBUG=-O0 \
    -DCARDEMO_WERROR=ON -DCARDEMO_BUILD_TESTS=OFF -DCARDEMO_BUILD_BENCH=OFF -DCARDEMO_WITH_SDL=OFF \
    -DCARDEMO_WITH_BOX2D=OFF "${cardemo_launcher[@]}" >/dev/null
  if ! cmake --build "$dir" --target cardemo -j"$jobs" >"$dir.log" 2>&1; then
    cat "$dir.log" >&2
    echo "determinism: $compiler $type: the build failed" >&2
    exit 1
  fi
  for replay in "${replays[@]}"; do
    name=$(basename "$replay" .replay)
    summary=$("$dir/cardemo" replay "$replay" --json - 2>/dev/null) && status=0 || status=$?
    hash=$(printf '%s' "$summary" | sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p')
    hashes["$name,$compiler-$type"]="${hash:-none}"
    if [ "$status" -ne 0 ]; then
      echo "determinism: $compiler $type: $name does not meet its expectations" >&2
      failed=$((failed + 1))
    fi
  done
done

printf '%-12s' replay
for spec in "${builds[@]}"; do IFS=: read -r c t _ <<<"$spec"; printf ' %-18s' "$c-$t"; done
echo
for replay in "${replays[@]}"; do
  name=$(basename "$replay" .replay)
  printf '%-12s' "$name"
  for spec in "${builds[@]}"; do
    IFS=: read -r c t _ <<<"$spec"
    printf ' %-18s' "${hashes["$name,$c-$t"]}"
  done
  echo
done
echo "determinism: ${#builds[@]} builds x ${#replays[@]} replays, $failed mismatches"
stage_end
[ "$failed" -eq 0 ]
