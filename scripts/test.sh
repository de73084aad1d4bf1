#!/usr/bin/env bash
# The README's test command and CI's (.ci/run). Installs what the tests need, then:
#   1. GCC -O2 with asserts (RelWithDebInfo without -g): builds everything (cardemo, tests,
#      benchmarks) and runs every CTest test (the golden replays here give the GCC -O2 hashes;
#      valgrind on two replays; the window end-to-end tests under Xvfb; the benchmark smoke runs
#      on every batch path);
#   2. determinism: the golden hashes again from `cardemo` alone in GCC Debug and GCC Release
#      (scripts/check-determinism.sh; the Clang hashes are the sanitizer tree's golden.* tests),
#      built beside stage 1's tests, as is the sanitizer tree of stage 4;
#   3. WebAssembly: the command line and the page built with Debian's emscripten (scripts/web.sh,
#      which installs it, chromium and puppeteer-core); the command line checked under node against
#      stage 1's cardemo, byte for byte (scripts/web-test.sh: every golden replay's summary, hash,
#      JSON and trace, bad input, pair queries); the page in headless chromium
#      (scripts/web-page-test.sh: every replay's native hash, level 1 driven by keys to PARKED and
#      its downloaded recording replayed natively, a malformed replay's FILE:LINE, a screenshot);
#   4. Clang ASan+UBSan, with the fuzz targets in the same tree: the window tests, and beside them
#      at low priority every other CTest test, then every fuzz target for CARDEMO_FUZZ_SECONDS
#      (default 10 here: each target replays its corpus and mutates beyond it; scripts/fuzz.sh
#      alone runs 60 s or more) (scripts/ci-sanitize.sh).
# Each stage prints its wall time and the CPU time (user+sys) of everything it ran (stage 1's
# includes the builds that ran beside its tests; those print their own).
#
# Usage: scripts/test.sh [--quick]
#   --quick   stage 1 only, without the slow labels (valgrind, stress, the window tests under
#             Xvfb): the edit-test loop. Incremental: reuses the build folder.
# Environment: CARDEMO_BUILD_DIR (default build-test; the other stages use BUILD-determinism,
# BUILD-web and BUILD-sanitize), CARDEMO_CTEST_ARGS (extra ctest arguments for stage 1),
# CARDEMO_FUZZ_SECONDS.
# ccache is used for every build when it is installed (scripts/packages.txt installs it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--quick]" >&2; exit 2 ;;
esac
"$root/scripts/ensure-packages.sh" $(grep -v '^#' "$root/scripts/packages.txt")
# shellcheck source=scripts/lib.sh
. "$root/scripts/lib.sh"
jobs=$(nproc)
build="${CARDEMO_BUILD_DIR:-$root/build-test}"
sanitize="${CARDEMO_SANITIZE_BUILD_DIR:-$build-sanitize}"

stage_begin "GCC -O2: build and every CTest test"
# -O2 with asserts, without -g: debug information was a third of this tree's compile time, and
# neither valgrind's reports nor a failing test need more than function names.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_WERROR=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 "${cardemo_launcher[@]}" >/dev/null
cmake --build "$build" -j"$jobs"
stage_step "build"
if [ "$quick" -eq 1 ]; then
  ctest --test-dir "$build" --output-on-failure -j"$jobs" -LE '^(valgrind|stress|platform)$' \
    ${CARDEMO_CTEST_ARGS:-}
  stage_end
  exit 0
fi
# The GCC suite spends much of its wall time waiting (the window tests hold keys for real seconds,
# the recording-kill test stops the game at random moments, valgrind runs alone at the end), so the
# next stages' builds (determinism, then the sanitizer tree) run beside it at the lowest priority
# (nice 19): the tests get the CPU whenever they want it, the builds take what is left. Their output
# goes to BUILD-background.log, printed after the suite.
background="$build-background.log"
(
  CARDEMO_DETERMINISM_BUILDS="gcc:Debug:g++ gcc:Release:g++" \
    nice -n 19 "$root/scripts/check-determinism.sh" "$build-determinism" &&
    CARDEMO_SANITIZE_BUILD_DIR="$sanitize" nice -n 19 "$root/scripts/ci-sanitize.sh" build
) >"$background" 2>&1 &
builds=$!
suite=0
# Every test but the window tests runs once: a golden, unit or property test that fails once has
# failed. The window tests run beside it (run_window_tests: one at a time, up to three tries, the
# retried ones named), as they mostly wait on wall-clock time.
run_window_tests "$build" ${CARDEMO_CTEST_ARGS:-} >"$build-window.log" 2>&1 &
window=$!
ctest --test-dir "$build" --output-on-failure -j"$jobs" -LE '^platform$' \
  ${CARDEMO_CTEST_ARGS:-} || suite=$?
wait "$window" || suite=$?
cat "$build-window.log"
stage_step "ctest"
built=0
wait "$builds" || built=$?
cat "$background"
stage_end
[ "$suite" -eq 0 ] || { echo "the GCC suite failed" >&2; exit 1; }
[ "$built" -eq 0 ] || { echo "the determinism check or the sanitizer build failed" >&2; exit 1; }

stage_begin "WebAssembly: the command line under node and the page in chromium against the GCC build"
CARDEMO_WEB_BUILD_DIR="$build-web" "$root/scripts/web.sh"
stage_step "build"
"$root/scripts/web-test.sh" "$build/cardemo" "$build-web/cardemo.js"
stage_step "node"
"$root/scripts/web-page-test.sh" "$build/cardemo" "$build-web"
stage_end

stage_begin "Clang ASan+UBSan: every CTest test, then every fuzz target"
CARDEMO_SANITIZE_BUILD_DIR="$sanitize" CARDEMO_FUZZ_SECONDS="${CARDEMO_FUZZ_SECONDS:-10}" \
  "$root/scripts/ci-sanitize.sh" test
stage_end
printf '\n== done: %d s wall\n' "$SECONDS"
