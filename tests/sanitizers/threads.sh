#!/usr/bin/env bash
# The thread checks run under ThreadSanitizer (scripts/check-tsan.sh): a
# scene of every kind and pipeline feature (one- and multi-pass, blending,
# depth, textures, mips, cubes, derivatives, discard, host stages, profile
# gathers) on the CPU pipeline at 1, 2, 3 and 8 threads gives the same
# hashes, and the Monte Carlo tracer the same result at 1 and 8 threads.
# (All 239 scenes at four thread counts take about 15 minutes under TSan;
# cli.threads runs them all without it.) Any data race TSan sees stops the
# run. Usage: threads.sh BINARY.
set -euo pipefail
bin="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
scenes="triangles-basic triangles-large triangles-alpha-blend triangles-depth triangles-slivers
  conformance-two-pass-rgba16f conformance-bloom-chain conformance-cube-rgba8-linear-mip-linear
  conformance-derivatives conformance-discard conformance-branch-texture-mip
  relief-mapping relief-bloom relief-two-layer thin-slab-fragment-backlit thin-slab-host-frontlit
  profile-parchment-multipole"
# The gather with an albedo map, its map at 128x128: the map's convolution
# is single-threaded host work (17 s a load at 512x512 under TSan, and
# nothing for TSan to check), the gather reads it on every thread alike.
textured="profile-skin-head-textured"
for t in 1 2 3 8; do
  { "$bin" render $scenes --backend cpu --threads "$t" --out "$work/t$t"
    "$bin" render $textured --set geometry.texture_size=128 --backend cpu --threads "$t" --out "$work/t$t"; } |
    python3 -c 'import json,sys
for line in sys.stdin:
    j = json.loads(line)
    print(j["scene"], j["hash"], *(o["name"] + "=" + o["hash"] for o in j["outputs"]))' | sort >"$work/hashes.$t"
  [ "$(wc -l <"$work/hashes.$t")" -eq "$(echo "$scenes $textured" | wc -w)" ] || fail "$t threads: a scene is missing"
  cmp -s "$work/hashes.1" "$work/hashes.$t" || fail "$t threads: hashes differ from 1 thread"
  echo "ok   CPU pipeline at $t threads: $(wc -l <"$work/hashes.$t") scenes, the same hashes as at 1"
done
for t in 1 8; do
  "$bin" slab --model mc --sigma-a 0.05 --sigma-s 2 --g 0.8 --thickness 1 --photons 40000 --threads "$t" >"$work/mc.$t"
done
cmp -s "$work/mc.1" "$work/mc.8" || fail "Monte Carlo: 8 threads differ from 1"
echo "ok   Monte Carlo at 1 and 8 threads: the same result"
