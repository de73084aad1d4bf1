#!/usr/bin/env bash
# The long form of the numerical stress suite (tests/stress, CTest label `stress`): the same tests
# as CI, with every case count and run length multiplied by CARDEMO_STRESS_SCALE (default here
# 100: 1e7-frame long runs, 100x the invariance drives and degenerate-geometry cases). CI runs
# scale 1. Extra arguments go to the test binary (e.g. --gtest_filter='LongRun*').
#   scripts/stress.sh                        # everything at scale 100
#   CARDEMO_STRESS_SCALE=10 scripts/stress.sh --gtest_filter='Invariance*'
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
build="${CARDEMO_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target test_stress -j"$(nproc)"
export CARDEMO_STRESS_SCALE="${CARDEMO_STRESS_SCALE:-100}"
echo "stress: CARDEMO_STRESS_SCALE=$CARDEMO_STRESS_SCALE"
"$build/tests/test_stress" "$@"
