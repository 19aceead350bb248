#!/usr/bin/env bash
# One built-in scene as its own CTest test (issue 13: `ctest -L relief`,
# `ctest -I` shards): compared on both backends against its criteria, its
# peak memory within the estimate (app/memory_budget.h), and its CPU image
# against the golden hash. Usage: scene_test.sh BINARY SCENE
set -euo pipefail
bin="$1"
scene="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/lib.sh"

"$bin" compare "$scene" --json --out "$work" >"$work/compare.json" || { cat "$work/compare.json"; fail "compare $scene"; }
[ -f "$work/$scene.diff.png" ] || fail "no heat map for $scene"
# A sanitizer build's shadow memory is not in the estimate.
python3 - "$work/compare.json" "${SHADERTWIN_SANITIZED:-}" <<'PY' || fail "compare $scene: $(cat "$work/compare.json")"
import json, sys
j = json.loads(open(sys.argv[1]).read())
assert j["pass"], j["failures"]
m = j["memory"]
assert sys.argv[2] or m["peak_mb"] <= m["estimate_mb"], ("peak memory beyond the estimate", m)
print("ok   %s: identical_float %g, peak %d of %d MiB estimated" % (j["scene"], j["identical_fraction_float"], m["peak_mb"], m["estimate_mb"]))
PY
"$bin" golden check "$scene"
