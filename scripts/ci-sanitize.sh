#!/usr/bin/env bash
# The sanitizer stage of CI: a clang build of everything with ASan+UBSan (CARDEMO_SANITIZE) and the
# libFuzzer targets (CARDEMO_FUZZ), warnings as errors; the whole CTest suite in it (golden hashes
# included: clang plus sanitizers must reproduce them); then every fuzz target for
# CARDEMO_FUZZ_SECONDS (default 60) from the committed corpus, two at a time. Fails on any test
# failure, sanitizer finding or fuzz crash. CARDEMO_SANITIZE_BUILD_DIR sets the build folder.
#   scripts/ci-sanitize.sh [build|test]   build: configure and build only; test: build (a no-op
#                                         when built) then the tests and the fuzzers; default both.
# In `test`, the window tests (label platform, one at a time) run beside the rest of the suite and
# then the fuzzers, which run at the lowest priority (nice 19): the window tests mostly wait on
# wall-clock time, and the others use the CPU they leave.
set -euo pipefail
phase=${1:-all}
root=$(cd "$(dirname "$0")/.." && pwd)
build="${CARDEMO_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
jobs=$(nproc)
# shellcheck source=scripts/lib.sh
. "$root/scripts/lib.sh"
stage_begin "sanitize ($phase)"
# Benchmarks are not tests: left out here to save build time. The fuzz targets link the same
# (sanitized, coverage-instrumented) libraries as the tests, so the core is compiled once.
# Line tables only: enough for the sanitizers' stack traces, and less to compile and link than
# full debug information.
CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARDEMO_WERROR=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only" -DCARDEMO_SANITIZE=ON -DCARDEMO_FUZZ=ON \
  -DCARDEMO_BUILD_BENCH=OFF "${cardemo_launcher[@]}" >/dev/null
cmake --build "$build" -j"$jobs"
stage_step build
[ "$phase" = build ] && exit 0
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# The random-case classes run at a tenth of their count (the full counts run in the plain build);
# the window tests run one at a time, up to three tries each: they hold keys for a wall-clock time
# and assume the game keeps up, which a sanitized build on a loaded machine may not (a sanitizer
# finding is deterministic and fails every try).
export CARDEMO_TEST_SCALE=${CARDEMO_TEST_SCALE:-0.1}
# The window tests mostly wait on wall-clock time, so the rest of the suite and then the fuzzers
# run beside them at the lowest priority (nice 19): the window tests get the CPU when they want it.
(
  suite=0
  nice -n 19 ctest --test-dir "$build" --output-on-failure -j"$jobs" -LE '^platform$' \
    ${CARDEMO_CTEST_ARGS:-} || suite=$?
  fuzzed=0
  CARDEMO_FUZZ_BUILD_DIR="$build" nice -n 19 "$root/scripts/fuzz.sh" "${CARDEMO_FUZZ_SECONDS:-60}" ||
    fuzzed=$?
  [ "$suite" -eq 0 ] || echo "sanitize: the suite failed" >&2
  [ "$fuzzed" -eq 0 ] || echo "sanitize: a fuzz target failed" >&2
  [ "$suite" -eq 0 ] && [ "$fuzzed" -eq 0 ]
) >"$build/suite-and-fuzz.log" 2>&1 &
rest=$!
platform=0
run_window_tests "$build" ${CARDEMO_CTEST_ARGS:-} || platform=$?
stage_step "ctest (platform)"
wait "$rest" && others=0 || others=$?
cat "$build/suite-and-fuzz.log"
stage_step "ctest (all but platform), then the fuzzers, beside it"
[ "$platform" -eq 0 ] && [ "$others" -eq 0 ]
