#!/usr/bin/env bash
# Builds the libFuzzer targets with the fuzz preset (the sanitize preset's clang build in build-sanitize/,
# -DOGIVE_FUZZ=ON; OGIVE_FUZZ_CXX names another clang++; after the sanitize preset's build there is nothing
# left to compile) and runs each for SECONDS (default 30) on a copy of its seed corpus
# (tests/fuzz/corpus/<name>/), so that new corpus entries never land in the repository. Exits non-zero when
# a target finds a crash, a leak, a timeout or runs out of memory; the input is saved under
# build-sanitize/artifacts/<target>/ and the log under build-sanitize/logs/. The targets run at the same
# time, one core each.
#   usage: .ci/fuzz.sh [SECONDS]
# Needs clang and libclang-rt-14-dev (.ci/install_deps.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "usage: .ci/fuzz.sh [SECONDS]  (a whole number > 0)" >&2; exit 2; }
build=build-sanitize
cxx="${OGIVE_FUZZ_CXX:-clang++}"

start=$(date +%s)
cmake --preset fuzz -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build --preset fuzz
echo "fuzz: build took $(($(date +%s) - start)) s"

# target, corpus and dictionary name, -max_len
targets=("fuzz_parse_values parse_values 4096" "fuzz_points_file points_file 65536")

# One target on a fresh copy of its corpus; its exit status and time go to files beside its log. The
# targets run side by side (libFuzzer uses one core each).
run_target() {
  local target=$1 name=$2 max_len=$3
  local corpus="$build/corpus/$name" artifacts="$build/artifacts/$target/" log="$build/logs/$target.log"
  rm -rf "$corpus" "$artifacts"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  cp tests/fuzz/corpus/"$name"/* "$corpus"/
  local t0 rc=0
  t0=$(date +%s)
  # halt_on_error etc. for the sanitizers; libFuzzer itself detects leaks, timeouts and RSS.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/tests/fuzz/$target" "$corpus" -dict="tests/fuzz/$name.dict" -max_total_time="$seconds" \
    -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts" \
    >"$log" 2>&1 || rc=$?
  echo "$rc" >"$log.rc"
  echo $(($(date +%s) - t0)) >"$log.seconds"
}

pids=()
for entry in "${targets[@]}"; do
  read -r target name max_len <<<"$entry"
  run_target "$target" "$name" "$max_len" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done

status=0
for entry in "${targets[@]}"; do
  read -r target name max_len <<<"$entry"
  corpus="$build/corpus/$name" artifacts="$build/artifacts/$target/" log="$build/logs/$target.log"
  rc=$(cat "$log.rc" 2>/dev/null || echo "?")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  entries=$(ls "$corpus" | wc -l)
  echo "fuzz: $target ran $(cat "$log.seconds" 2>/dev/null || echo "?") s, ${execs:-?} executions (${rate:-?}/s), corpus ${entries} files, exit $rc"
  if [[ "$rc" != 0 ]]; then
    status=1
    echo "fuzz: $target FAILED; the last lines of $log:" >&2
    tail -n 40 "$log" >&2
    echo "fuzz: reproduce with: $build/tests/fuzz/$target $artifacts<file>" >&2
    ls -l "$artifacts" >&2
  fi
done
echo "fuzz: total $(($(date +%s) - start)) s"
exit "$status"
