#!/usr/bin/env bash
# Runs the libFuzzer targets of a fuzz build for a while each, on a copy of
# the seed corpus (fuzz/corpus/<target>/ is never written). Exits non-zero
# when a target crashes, hangs (30 s for one input), runs out of memory
# (4 GB) or trips a sanitizer; the input that did is kept in the work folder.
# Usage: fuzz/run.sh BUILD_DIR SECONDS_PER_TARGET [WORK_DIR] [TARGET...]
# (CI: a few seconds each; the long run of docs/reliability.md: hours.)
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$1"
seconds="$2"
work="${3:-$(mktemp -d)}"
shift $(( $# < 3 ? $# : 3 ))
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(scene_fuzzer layer_file_fuzzer image_fuzzer raster_fuzzer)
source "$src/scripts/sanitizer-env.sh"
# One target per core at a time (FUZZ_JOBS, default nproc): each target is a
# single process, so on two cores two targets fuzz in the time of one. The
# lines are printed in the targets' order once all have finished.
jobs_max="${FUZZ_JOBS:-$(nproc)}"

fuzz_one() {  # fuzz_one TARGET: runs it, leaves its line in $work/TARGET/result and its exit code in .../rc
  local t="$1" log rc runs rate extra
  mkdir -p "$work/$t/new"
  log="$work/$t/log"
  set +e
  "$build/fuzz/$t" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$work/$t/" "$work/$t/new" "$src/fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  extra=$(grep -E '^raster_fuzzer: ' "$log" || true)
  if [ "$rc" -ne 0 ]; then
    { echo "FAIL $t (exit $rc): $(ls "$work/$t" | grep -E '^(crash|timeout|oom|leak)-' | head -3)"
      grep -E 'ERROR|runtime error|SUMMARY|deadly signal' "$log" | head -5; } >"$work/$t/result"
  else
    echo "ok   $t: ${runs:-?} inputs in ${seconds} s (${rate:-?}/s)${extra:+; $extra}" >"$work/$t/result"
  fi
  echo "$rc" >"$work/$t/rc"
}

for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
  fuzz_one "$t" &
done
wait
status=0
for t in "${targets[@]}"; do
  if [ "$(cat "$work/$t/rc" 2>/dev/null || echo 1)" -ne 0 ]; then
    cat "$work/$t/result" >&2 2>/dev/null || echo "FAIL $t: no result" >&2
    status=1
  else
    cat "$work/$t/result"
  fi
done
exit $status
