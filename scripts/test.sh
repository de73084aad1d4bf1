#!/usr/bin/env bash
# Installs what the tests need, configures, builds and runs every test (ctest), then checks that the
# golden replays give the same hashes in a Debug build (determinism across build types).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
jobs=$(nproc)
build="${CARDEMO_BUILD_DIR:-$root/build-test}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_WERROR=ON
cmake --build "$build" -j"$jobs"
ctest --test-dir "$build" --output-on-failure -j"$jobs" ${CARDEMO_CTEST_ARGS:-}

# The same replays in a Debug build must meet the same expectations (hashes included).
debug="$build-debug"
cmake -S "$root" -B "$debug" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCARDEMO_WERROR=ON -DCARDEMO_BUILD_TESTS=OFF >/dev/null
cmake --build "$debug" --target cardemo -j"$jobs"
pass=0 fail=0
for replay in "$root"/assets/replays/*.replay; do
  if "$debug/cardemo" replay "$replay" >/dev/null; then pass=$((pass + 1)); else
    echo "Debug build: $replay does not meet its expectations" >&2; fail=$((fail + 1)); fi
done
echo "debug-replays: $pass passed, $fail failed"
[ "$fail" -eq 0 ]

# Sanitizers (ASan+UBSan, clang) over the whole suite, then every fuzz target for 60 s.
"$root/scripts/ci-sanitize.sh"
