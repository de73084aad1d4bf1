# Sourced by the test scripts: stage timing and the compiler launcher. Not run on its own.

# -DCMAKE_CXX_COMPILER_LAUNCHER=ccache when ccache is installed (a developer's rebuilds hit its
# cache; CI's fresh machine starts cold, so CI's times do not count on it).
cardemo_launcher=()
if command -v ccache >/dev/null; then
  cardemo_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # The tests' precompiled header: without these ccache declines to cache the test files.
  export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}
fi

# CPU seconds (user+sys) used so far by this shell's finished children, from bash's `times` (run in
# this shell, not in a command substitution, whose subshell has children of its own).
cardemo_times=""
cpu_seconds() {
  if [ -z "$cardemo_times" ]; then
    cardemo_times=$(mktemp)
    trap 'rm -f "$cardemo_times" "$cardemo_times.now"' EXIT
  fi
  times >"$cardemo_times"
  tail -1 "$cardemo_times" | awk '{
    t = 0
    for (i = 1; i <= 2; i++) { split($i, p, "m"); sub("s", "", p[2]); t += p[1] * 60 + p[2] }
    printf "%.1f", t
  }'
}

# stage_begin NAME / stage_step PART / stage_end: a stage's banner, then its wall and CPU time.
stage_begin() {
  cpu_seconds >/dev/null # creates the scratch file in this shell
  cpu_seconds >"$cardemo_times.now"
  stage_name=$1 stage_wall=$SECONDS stage_cpu=$(<"$cardemo_times.now")
  step_wall=$SECONDS step_cpu=$stage_cpu
  printf '\n== %s (%d s since start)\n' "$1" "$SECONDS"
}
stage_step() {
  local cpu
  cpu_seconds >"$cardemo_times.now"
  cpu=$(<"$cardemo_times.now")
  printf -- '-- %s: %s, %d s wall, %.0f s CPU\n' "$stage_name" "$1" $((SECONDS - step_wall)) \
    "$(awk -v a="$cpu" -v b="$step_cpu" 'BEGIN { print a - b }')"
  step_wall=$SECONDS step_cpu=$cpu
}
stage_end() {
  local cpu
  cpu_seconds >"$cardemo_times.now"
  cpu=$(<"$cardemo_times.now")
  printf -- '-- %s: %d s wall, %.0f s CPU (user+sys)\n' "$stage_name" $((SECONDS - stage_wall)) \
    "$(awk -v a="$cpu" -v b="$stage_cpu" 'BEGIN { print a - b }')"
}

# run_window_tests BUILD [CTEST ARGS...]: the tests of kind `platform` (the real window under
# Xvfb), one at a time with up to three tries each, the only tests that get a second try: they
# hold keys for wall-clock time and assume the game keeps up, which a loaded machine may not (a
# real failure fails every try). Prints the names of the tests that needed another try.
run_window_tests() {
  local build=$1 log status=0 retried
  shift
  log="$build/window-tests.log"
  ctest --test-dir "$build" --output-on-failure -j1 -L '^platform$' --repeat until-pass:3 "$@" \
    >"$log" 2>&1 || status=$?
  cat "$log"
  retried=$(sed -nE 's/.*Test +#[0-9]+: ([^ ]+) .*\*\*\*.*/\1/p' "$log" | sort -u)
  if [ -n "$retried" ]; then
    printf 'window tests that failed a try: %s\n' "$(echo "$retried" | tr '\n' ' ')"
  else
    echo "no window test needed a second try"
  fi
  return "$status"
}
