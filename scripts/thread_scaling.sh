#!/usr/bin/env bash
# 1 -> 2 thread scaling of the CPU pipeline for built-in scenes: runs the
# micro-benchmark BM_CpuFrame/<scene> at 1 and at 2 threads alternately,
# ROUNDS times (0.3 s each), and prints the medians and their ratio. The
# machine is shared; alternating keeps slow spells from favouring one side.
# Usage: scripts/thread_scaling.sh [ROUNDS] SCENE...   (from the repository root)
set -euo pipefail
rounds=12
if [[ "${1:-}" =~ ^[0-9]+$ ]]; then rounds="$1"; shift; fi
bench=build/bench/microbench
[ -x "$bench" ] || { echo "thread_scaling: build first ($bench missing)" >&2; exit 2; }
for scene in "$@"; do
  for _ in $(seq "$rounds"); do
    for t in 1 2; do
      "$bench" --benchmark_filter="BM_CpuFrame/$scene/threads:$t\$" --benchmark_min_time=0.3 \
        --benchmark_format=csv 2>/dev/null | tail -n +2 | sed "s/^/$t,/"
    done
  done | python3 -c '
import csv, statistics, sys
times = {"1": [], "2": []}
for row in csv.reader(sys.stdin):
    times[row[0]].append(float(row[3]))
one, two = statistics.median(times["1"]), statistics.median(times["2"])
rounds = len(times["1"])
print(f"{sys.argv[1]}: 1 thread {one:.3f} ms, 2 threads {two:.3f} ms, scaling {one / two:.2f} (medians of {rounds})")
' "$scene"
done
