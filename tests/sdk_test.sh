#!/usr/bin/env bash
# The installed package as a user meets it (issue 13): `cmake --install` of
# this build into a fresh prefix; examples/wrap_lighting, copied out of the
# tree, configured and built against it with shadertwin_add_technique; its
# tool's compare and golden check; and every way a user's technique is
# refused: at configure time by CMake, and when the tool starts with one
# line and exit code 2.
# Usage: sdk_test.sh SOURCE_DIR BUILD_DIR CXX_COMPILER
set -euo pipefail
src="$1"
build="$2"
cxx="$3"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/lib.sh"

prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "install"; }
for f in bin/shadertwin lib/cmake/shadertwin/shadertwinConfig.cmake include/shadertwin/sdk/technique.h \
         share/shadertwin/golden/hashes.json share/shadertwin/tool_main.cpp; do
  [ -e "$prefix/$f" ] || fail "the install has no $f"
done
# Installed tools read the prefix, not the source tree: a scene taken out of
# the prefix is gone from the installed `shadertwin`.
rm "$prefix/share/shadertwin/scenes/triangles-basic.json"
"$prefix/bin/shadertwin" list >"$work/list"
grep -qx triangles-depth "$work/list" || fail "the installed shadertwin lists no built-in scenes"
! grep -qx triangles-basic "$work/list" || fail "the installed shadertwin reads scenes from outside its prefix"
echo "ok   installed shadertwin: $(wc -l <"$work/list") scenes from $prefix/share/shadertwin"

# The example, out of the tree, and the test's broken technique beside it.
project="$work/project"
cp -r "$src/examples/wrap_lighting" "$project"
rm -rf "$project/build"
cp -r "$src/tests/sdk/broken" "$project/broken"
echo 'add_subdirectory(broken)' >>"$project/CMakeLists.txt"
configure() { cmake -S "$1" -B "$2" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release; }
configure "$project" "$project/build" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure the example"; }
start=$(date +%s)
cmake --build "$project/build" -j 2 >"$work/build.log" 2>&1 || { tail -40 "$work/build.log"; fail "build the example"; }
echo "ok   example built against the install in $(( $(date +%s) - start )) s"
tool="$project/build/wraptwin"
broken="$project/build/broken/brokentwin"

# Its scenes beside the built-in ones, bit-identical to llvmpipe.
"$tool" list >"$work/list"
grep -qx wrap-sphere-front "$work/list" && grep -qx thin-slab-fragment-backlit "$work/list" ||
  fail "wraptwin does not list its scenes and the built-in ones"
! grep -qx triangles-basic "$work/list" || fail "wraptwin reads built-in scenes from outside the prefix"
"$tool" compare wrap-sphere-front wrap-sphere-back --json --out "$work/compare" >"$work/compare.jsonl" ||
  { cat "$work/compare.jsonl"; fail "wraptwin compare"; }
python3 - "$work/compare.jsonl" <<'PY' || fail "the example's scenes are not bit-identical to llvmpipe"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
assert [r["scene"] for r in rows] == ["wrap-sphere-front", "wrap-sphere-back"], rows
for r in rows:
    assert r["pass"] and r["identical_fraction_float"] == 1 and r["coverage_mismatch"] == 0, r
PY
echo "ok   wraptwin compare: both scenes bit-identical to llvmpipe"
# Its goldens live in its own file, the built-in ones in the prefix.
"$tool" golden check wrap-sphere-front wrap-sphere-back thin-slab-fragment-backlit >"$work/golden.txt" ||
  { cat "$work/golden.txt"; fail "wraptwin golden check"; }
[ "$(grep -c ' ok$' "$work/golden.txt")" -eq 3 ] || fail "golden check: $(cat "$work/golden.txt")"
sed -i 's/"wrap-sphere-back": "[0-9A-F]*"/"wrap-sphere-back": "0000"/' "$project/golden/hashes.json"
set +e; "$tool" golden check wrap-sphere-back >"$work/golden.txt" 2>&1; rc=$?; set -e
[ "$rc" -eq 1 ] || fail "golden check took a changed hash (exit $rc)"
echo "ok   wraptwin golden check: its own golden file, a changed hash fails"
"$broken" compare broken-scene --out "$work/broken" >/dev/null || fail "the broken technique's own scene"

# Refused when the tool starts: one line, exit 2, nothing written (lib.sh).
for how in twin-twice:"fragment twin 'broken' registered twice" builtin-twin:"vertex twin 'interp' registered twice" \
           kind-twice:"scene kind 'triangles' registered twice" no-builder:"scene kind 'nothing' has no builder" \
           no-glsl:"fragment twin 'ghost' has no ghost.frag"; do
  SHADERTWIN_TEST_BREAK="${how%%:*}" expect_refused "technique: ${how%%:*}" "${how#*:}" "$broken" compare broken-scene
done
cp "$src/scenes/thin-slab-fragment-backlit.json" "$project/broken/scenes/"
expect_refused "a scene name taken by a built-in one" "is in two places" "$broken" compare broken-scene
rm "$project/broken/scenes/thin-slab-fragment-backlit.json"
echo '{"kind": "no-such-kind", "width": 8, "height": 8}' >"$project/broken/scenes/broken-kind.json"
expect_refused "a scene of a kind no technique builds" "unknown scene kind 'no-such-kind'" "$broken" compare broken-kind
rm "$project/broken/scenes/broken-kind.json"
mv "$project/broken/broken.frag" "$work/broken.frag"
expect_refused "a GLSL file gone since the build" "technique broken: no GLSL file" "$broken" compare broken-scene
mv "$work/broken.frag" "$project/broken/broken.frag"

# Refused by CMake when the project is configured.
expect_configure_error() {
  local what="$1" expected="$2" call="$3"
  local p="$work/bad-project"
  rm -rf "$p"; mkdir -p "$p/glsl"
  cp "$project/glsl/"* "$p/glsl/"; cp -r "$project/kernels" "$p/kernels"
  printf 'cmake_minimum_required(VERSION 3.25)\nproject(bad LANGUAGES CXX)\nfind_package(shadertwin REQUIRED)\n%s\n' \
    "$call" >"$p/CMakeLists.txt"
  set +e; configure "$p" "$p/build" >"$work/bad-configure.log" 2>&1; local rc=$?; set -e
  [ "$rc" -ne 0 ] || fail "$what: configured"
  # (CMake folds long messages over several lines.)
  grep -q -- "$expected" "$work/bad-configure.log" || { cat "$work/bad-configure.log"; fail "$what: does not say '$expected'"; }
  echo "ok   configure refuses $what: $(grep -m1 -- "$expected" "$work/bad-configure.log" | sed 's/^ *//')"
}
twins="TWINS kernels/wrap_vert.cpp kernels/wrap_frag.cpp kernels/wrap_scene.cpp kernels/wrap_technique.cpp"
expect_configure_error "a GLSL file that does not exist" "shadertwin_add_technique(wrap): no file" \
  "shadertwin_add_technique(NAME wrap GLSL glsl/wrap.vert glsl/wrap.geom $twins)"
grep -q "glsl/wrap.geom" "$work/bad-configure.log" || fail "the configure error does not name the missing file"
expect_configure_error "a technique added twice to one tool" "already has a technique" \
  "shadertwin_add_technique(NAME wrap GLSL glsl/wrap.vert glsl/wrap.frag $twins)
shadertwin_add_technique(NAME wrap GLSL glsl/wrap.vert glsl/wrap.frag $twins)"
expect_configure_error "a name that is no C identifier" "must be a C identifier" \
  "shadertwin_add_technique(NAME wrap-lighting GLSL glsl/wrap.vert glsl/wrap.frag $twins)"
