#!/usr/bin/env bash
# Every lane width and both compilers give the same bits: builds
# tests/lane_hashes (and the lane operations' unit tests, lane_unit_tests)
# for the other lane widths of simd/lanes.h, each in its own build folder,
# and checks that they reproduce tests/golden/hashes.json for every
# built-in scene, as this build does (cli.compare_builtin):
# - avx2 (8 lanes with AVX2 intrinsics) built by clang++ at the release
#   level, -O3: the second compiler's check (the sanitizer builds are
#   clang++ at -O2 and check the same hashes in their cli.compare_builtin);
# - generic (8 lanes of plain vector code, without AVX, FMA3 or SSSE3, so
#   every portable fallback runs) built by this build's compiler at -O1.
# Usage: lane_width_test.sh SOURCE_DIR BUILD_DIR.
set -euo pipefail
src="$1"
build="$2"
golden="$src/tests/golden/hashes.json"
source "$(dirname "$0")/lib.sh"

check() {  # check LABEL HASHES_FILE: every scene's hash (after the header line) is its golden
  local label="$1" file="$2" n
  n=$(python3 - "$golden" "$file" <<'PY'
import json, sys
golden = json.load(open(sys.argv[1]))
rows = [line.split() for line in open(sys.argv[2]).read().splitlines()[1:] if line.strip()]
for scene, got in rows:
    if golden.get(scene, "none") != got:
        sys.exit(f"{scene} hash {got}, golden {golden.get(scene, 'none')}")
print(len(rows))
PY
) || fail "$label: a hash differs from the golden one (above)"
  [ "$n" -ge 35 ] || fail "$label: only $n scenes"
  echo "ok   $label ($(head -1 "$file")): $n scenes match the goldens"
}

# This build's own width is cli.compare_builtin's: its CPU images are held
# to the same goldens.

# The other widths are built with this build's sanitizers, so that a
# sanitizer build's run covers them too.
cache_value_of() { sed -n "s/^$2:[A-Z]*=//p" "$1/CMakeCache.txt"; }
cache_value() { cache_value_of "$build" "$1"; }
sanitize=(-DSHADERTWIN_SANITIZE="$(cache_value SHADERTWIN_SANITIZE)")
clang=$(command -v clang++ || true)
[ -n "$clang" ] || fail "clang++ is missing (the avx2 flavour is the second compiler's check): ./scripts/install-deps.sh clang"

for flavour in avx2 generic; do
  dir="$build/lanes-$flavour"
  # LTO off, another compiler or -O1: other code generation from the same
  # source must give the same bits too. (Configured every time: it is
  # quick, and it picks up new targets in a folder left by an earlier run.)
  if [ "$flavour" = avx2 ]; then
    compiler="$clang" flags=(-DCMAKE_BUILD_TYPE=Release)
  else
    compiler="$(cache_value CMAKE_CXX_COMPILER)"
    flags=(-DSHADERTWIN_FMA=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1)
  fi
  # A folder another compiler configured starts afresh (CMake keeps a
  # folder's compiler).
  if [ -f "$dir/CMakeCache.txt" ] && [ "$(cache_value_of "$dir" CMAKE_CXX_COMPILER)" != "$compiler" ]; then
    rm -rf "$dir"
  fi
  flags+=(-DCMAKE_CXX_COMPILER="$compiler")
  cmake -S "$src" -B "$dir" "${sanitize[@]}" "${flags[@]}" -DSHADERTWIN_SIMD="$flavour" \
    -DCMAKE_INTERPROCEDURAL_OPTIMIZATION=OFF >/dev/null
  cmake --build "$dir" --target lane_hashes lane_unit_tests -j "$(nproc)" >/dev/null
  "$dir/tests/lane_unit_tests" --gtest_brief=1 >"$dir/lane_unit_tests.out" 2>&1 ||
    { cat "$dir/lane_unit_tests.out" >&2; fail "$flavour: lane unit tests"; }
  echo "ok   $flavour ($(basename "$(cache_value_of "$dir" CMAKE_CXX_COMPILER)")): $(tail -1 "$dir/lane_unit_tests.out")"
  "$dir/tests/lane_hashes" 2 >"$dir/lane_hashes.out"
  check "$flavour" "$dir/lane_hashes.out"
done
