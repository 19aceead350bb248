#!/usr/bin/env bash
# Regenerates the pictures and charts under docs/images/ from the built
# binary: the eight thin-slab scenes (CPU backend; bit-identical to GL) as
# 256x256 RGB PNGs, the thin-slab sweep charts and tables, and the optics
# figures (docs/optics.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/shadertwin
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=docs/images/thin-slab
mkdir -p "$out"
scenes=$("$bin" list | grep '^thin-slab-' | grep -v sweep)
"$bin" render $scenes --out "$tmp" >/dev/null
for s in $scenes; do
  # Drop alpha (it holds the blend's transmittance, not coverage) and halve.
  oiiotool "$tmp/$s.cpu.exr" --ch R,G,B --resize 256x256 -d uint8 -o "$out/$s.png"
done
"$bin" sweep thin-slab --out "$tmp/sweep" >/dev/null
cp "$tmp"/sweep/*.svg "$tmp"/sweep/thin-slab-sweep.md "$out/"
echo "wrote $out" >&2
# Optics: Figure 2, Table 3 skin, speed/accuracy charts and tables.
"$bin" optics-figures --out docs/images/optics --photons 400000 >/dev/null
echo "wrote docs/images/optics" >&2
