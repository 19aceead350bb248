#!/usr/bin/env bash
# The thread checks run under ThreadSanitizer (scripts/check-tsan.sh): every
# built-in scene on the CPU pipeline at 1, 2, 3 and 8 threads gives the same
# hashes, and the Monte Carlo tracer the same result at 1 and 8 threads.
# Any data race TSan sees stops the run. Usage: threads.sh BINARY.
set -euo pipefail
bin="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
scenes=$("$bin" list)
for t in 1 2 3 8; do
  "$bin" render $scenes --backend cpu --threads "$t" --out "$work/t$t" |
    python3 -c 'import json,sys
for line in sys.stdin:
    j = json.loads(line)
    print(j["scene"], j["hash"], *(o["name"] + "=" + o["hash"] for o in j["outputs"]))' | sort >"$work/hashes.$t"
  [ "$(wc -l <"$work/hashes.$t")" -eq "$(echo "$scenes" | wc -w)" ] || fail "$t threads: a scene is missing"
  cmp -s "$work/hashes.1" "$work/hashes.$t" || fail "$t threads: hashes differ from 1 thread"
  echo "ok   CPU pipeline at $t threads: $(wc -l <"$work/hashes.$t") scenes, the same hashes as at 1"
done
for t in 1 8; do
  "$bin" slab --model mc --sigma-a 0.05 --sigma-s 2 --g 0.8 --thickness 1 --photons 40000 --threads "$t" >"$work/mc.$t"
done
cmp -s "$work/mc.1" "$work/mc.8" || fail "Monte Carlo: 8 threads differ from 1"
echo "ok   Monte Carlo at 1 and 8 threads: the same result"
