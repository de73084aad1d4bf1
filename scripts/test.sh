#!/usr/bin/env bash
# Installs what the tests need, configures, builds and runs every test (ctest), then checks that the
# golden replays give the same hashes with GCC and Clang in Debug and Release (determinism).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
jobs=$(nproc)
build="${CARDEMO_BUILD_DIR:-$root/build-test}"
stage() { printf '\n== %s (%ds since start)\n' "$1" "$SECONDS"; }

stage "GCC RelWithDebInfo: build and every CTest test"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_WERROR=ON
cmake --build "$build" -j"$jobs"
ctest --test-dir "$build" --output-on-failure -j"$jobs" ${CARDEMO_CTEST_ARGS:-}

stage "Determinism: golden hashes with GCC Debug, GCC Release, Clang Release"
"$root/scripts/check-determinism.sh" "$build-determinism"

stage "Clang ASan+UBSan: every CTest test, then every fuzz target for 60 s"
"$root/scripts/ci-sanitize.sh"
stage "done"
