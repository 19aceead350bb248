#!/usr/bin/env bash
# A user's tool gives the same bits with and without link-time optimisation
# (issue 25): this build installed into a fresh prefix, examples/wrap_lighting
# built against it twice, SHADERTWIN_LTO=OFF (the edit loop's default in a
# RelWithDebInfo build: the libraries' fat objects linked as plain code) and
# ON (a Release build's default), and both tools' images hashed. Label
# `long` (the LTO link takes half a minute or more): CI runs it after
# ./test.sh (.ci/run).
# Usage: sdk_lto_test.sh SOURCE_DIR BUILD_DIR CXX_COMPILER
set -euo pipefail
source "$(dirname "$0")/lib.sh"
sdk_setup "$@"

grep -q "set(shadertwin_LTO ON)" "$prefix/lib/cmake/shadertwin/shadertwinConfig.cmake" ||
  { echo "ok   skipped: this build's libraries hold no LTO objects (a sanitizer build)"; exit 0; }
project="$work/project"
cp -r "$src/examples/wrap_lighting" "$project"
rm -rf "$project/build"
for flavour in plain lto; do
  # Each flavour by its build type's default: RelWithDebInfo links without
  # LTO, Release with.
  type=RelWithDebInfo; [ "$flavour" = lto ] && type=Release
  cmake -S "$project" -B "$project/$flavour" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_BUILD_TYPE=$type >"$work/configure-$flavour.log" 2>&1 || { cat "$work/configure-$flavour.log"; fail "configure ($type)"; }
  start=$(date +%s)
  cmake --build "$project/$flavour" -j 2 >"$work/build-$flavour.log" 2>&1 || { tail -40 "$work/build-$flavour.log"; fail "build ($type)"; }
  echo "ok   $type build: $(( $(date +%s) - start )) s"
done
grep -q -- "-flto" "$project/lto/CMakeFiles/wraptwin.dir/link.txt" || fail "a Release build did not link with LTO"
! grep -q -- " -flto" "$project/plain/CMakeFiles/wraptwin.dir/link.txt" || fail "a RelWithDebInfo build linked with LTO"
for scene in wrap-sphere-front wrap-sphere-back; do
  hash() { "$1" render "$scene" --backend cpu --out "$work/$2" | python3 -c 'import json,sys; print(json.load(sys.stdin)["hash"])'; }
  plain=$(hash "$project/plain/wraptwin" plain)
  lto=$(hash "$project/lto/wraptwin" lto)
  [ "$plain" = "$lto" ] || fail "$scene: $plain without LTO, $lto with"
done
# The golden file was made by an LTO build of the tool; both flavours agree with it.
for flavour in plain lto; do
  "$project/$flavour/wraptwin" golden check wrap-sphere-front wrap-sphere-back >"$work/golden-$flavour.txt" ||
    { cat "$work/golden-$flavour.txt"; fail "golden check ($flavour)"; }
done
echo "ok   with and without LTO: the same hashes of both scenes, and the golden file's"
