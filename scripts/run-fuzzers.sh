#!/usr/bin/env bash
# Runs the libFuzzer targets built by the `fuzz` preset (make fuzz), each for a while:
#   scripts/run-fuzzers.sh SECONDS JOBS TARGET...
# Each target starts from its committed seeds (fuzz/corpus/TARGET) plus what earlier runs
# found (build/fuzz/corpus/TARGET, kept between runs), JOBS targets at a time. Prints one
# line per target (executions, coverage, new corpus entries) and exits 1 if any target
# found a crash, a sanitizer error, a leak, a timeout or an out-of-memory (the input is
# saved in build/fuzz/artifacts/TARGET/). FUZZ_TIMEOUT (default 10) is the wall-clock
# seconds one input may take; raise it when the fuzzers run at low priority beside other
# work, where a starved process can exceed it without any slow input.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:?seconds per target}
jobs=${2:?targets at a time}
shift 2
build=build/fuzz
mkdir -p "$build/logs"

run_one() {
  local target=$1 seconds=$2 build=$3 timeout=${FUZZ_TIMEOUT:-10}
  local binary="$build/fuzz/fuzz_$target"
  local corpus="$build/corpus/$target" artifacts="$build/artifacts/$target/"
  local dict="fuzz/dict/$target.dict"
  mkdir -p "$corpus" "$artifacts"
  local options=(-max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -max_len=4096
                 -print_final_stats=1 -artifact_prefix="$artifacts")
  [ -f "$dict" ] && options+=(-dict="$dict")
  if "$binary" "${options[@]}" "$corpus" "fuzz/corpus/$target" >"$build/logs/$target.log" 2>&1; then
    echo "ok   $target"
  else
    echo "FAIL $target"
  fi
}
export -f run_one

printf '%s\n' "$@" | xargs -P "$jobs" -I{} bash -c "run_one {} $seconds $build" \
  | tee "$build/logs/summary.txt"

status=0
for target in "$@"; do
  log="$build/logs/$target.log"
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}' || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | awk '{print $2}' || true)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | awk '{print $2}' || true)
  entries=$(ls "$build/corpus/$target" | wc -l)
  printf '%-16s executions %-10s coverage (edges) %-6s features %-7s corpus %s\n' \
    "$target" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$entries"
  if grep -qx "FAIL $target" "$build/logs/summary.txt"; then
    status=1
    echo "---- $target failed; the end of $log:"
    tail -40 "$log"
  fi
done
exit $status
