#!/usr/bin/env bash
# Runs clang-tidy (the checks in .clang-tidy) over every source file of src/ and lab/ (not its tests)
# that the build compiles,
# in parallel, with that build's flags (compile_commands.json), and fails on any warning.
#   scripts/tidy.sh [BUILD_DIR]     (default: build-tidy; configured here when it has no database)
# The build must not be a unity build: its database lists the unity sources, not the files of src/
# (only the instruction-set files, compiled apart, would be checked). A directory configured here
# has CARDEMO_UNITY_BUILD=OFF; nothing needs to be built in it.
# CARDEMO_TIDY_JOBS sets the parallelism (default: nproc).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${1:-$root/build-tidy}"
if [ ! -f "$build/compile_commands.json" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCARDEMO_UNITY_BUILD=OFF >/dev/null
fi
if grep -q '^CARDEMO_UNITY_BUILD:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "tidy.sh: $build is a unity build, whose database names the unity sources rather than" \
    "the files of src/; configure one with -DCARDEMO_UNITY_BUILD=OFF (or run without an argument)" >&2
  exit 2
fi
tidy=$(command -v clang-tidy-14 || command -v clang-tidy)
jobs=${CARDEMO_TIDY_JOBS:-$(nproc)}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# The src/ and lab/ files the build compiles (optional parts such as SDL or Box2D only when
# configured; lab/tests is a test suite, as tests/ is).
files=$(python3 - "$build/compile_commands.json" "$root/src/" "$root/lab/" <<'PY'
import json, os, sys
entries = json.load(open(sys.argv[1]))
src, lab = (os.path.realpath(d) for d in sys.argv[2:4])
def wanted(f):
    return f.startswith(src + os.sep) or (f.startswith(lab + os.sep) and
                                          not f.startswith(os.path.join(lab, "tests") + os.sep))
print("\n".join(sorted({os.path.realpath(e["file"]) for e in entries
                        if wanted(os.path.realpath(e["file"]))})))
PY
)
start=$(date +%s)
status=0
# One clang-tidy per file, `jobs` at a time; -quiet drops the per-file summary lines.
printf '%s\n' "$files" | xargs -P "$jobs" -n 1 "$tidy" -quiet -p "$build" >"$log" 2>&1 || status=$?
count=$(printf '%s\n' "$files" | wc -l)
findings=$(grep -cE ': (warning|error): ' "$log" || true)
echo "clang-tidy: $count files, $findings findings, $(($(date +%s) - start)) s with $jobs jobs"
if [ "$findings" -ne 0 ] || [ "$status" -ne 0 ]; then
  grep -E -A3 ': (warning|error): ' "$log" >&2 || cat "$log" >&2
  exit 1
fi
