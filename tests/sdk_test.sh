#!/usr/bin/env bash
# The installed package as a user meets it (issue 13): `cmake --install` of
# this build into a fresh prefix; examples/wrap_lighting, copied out of the
# tree, configured and built against it with shadertwin_add_technique; its
# tool's compare and golden check; and every way a user's technique is
# refused: at configure time by CMake, and when the tool starts with one
# line and exit code 2.
# Usage: sdk_test.sh SOURCE_DIR BUILD_DIR CXX_COMPILER
set -euo pipefail
source "$(dirname "$0")/lib.sh"
sdk_setup "$@"

for f in bin/shadertwin lib/libshadertwin_oiio.so lib/cmake/shadertwin/shadertwinConfig.cmake include/shadertwin/sdk/technique.h \
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
# Without LTO (the edit loop's build: the libraries' fat objects link as
# plain code); tests/sdk_lto_test.sh checks the LTO build gives the same bits.
configure() { cmake -S "$1" -B "$2" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release "${@:3}"; }
configure "$project" "$project/build" -DSHADERTWIN_LTO=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configure the example"; }
start=$(date +%s)
cmake --build "$project/build" -j 2 >"$work/build.log" 2>&1 || { tail -40 "$work/build.log"; fail "build the example"; }
echo "ok   example built against the install without LTO in $(( $(date +%s) - start )) s"
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
# The tool has every command for its scenes: render through either GL
# platform, bench, and a report with its own technique's part beside the
# built-in ones, whose sweep charts come from the prefix.
"$tool" render wrap-sphere-front --backend gl --gl egl --out "$work/render" | grep -q '"gl_platform":"egl"' ||
  fail "wraptwin render through EGL"
[ "$("$tool" bench wrap-sphere-front --frames 2 --json | wc -l)" -eq 2 ] || fail "wraptwin bench: one line per backend"
rm "$prefix/share/shadertwin/sweeps/relief/relief-sweep-85deg.svg"  # so the prefix's charts are told from the tree's
"$tool" report 'wrap-*' relief-mapping --set width=64 --set height=48 --frames 1 --out "$work/report" >/dev/null ||
  fail "wraptwin report"
grep -q 'id="t-wrap"' "$work/report/index.html" && grep -q 'id="t-relief"' "$work/report/index.html" ||
  fail "the report has no part for the user's technique or the built-in one"
[ "$(ls "$work/report/charts/" | grep -c '^relief-.*\.svg$')" -eq 4 ] || fail "the report did not take the sweep charts from the prefix"
echo "ok   wraptwin render (EGL), bench and report"
# Its goldens live in its own file, the built-in ones in the prefix.
"$tool" golden check wrap-sphere-front wrap-sphere-back thin-slab-fragment-backlit >"$work/golden.txt" ||
  { cat "$work/golden.txt"; fail "wraptwin golden check"; }
[ "$(grep -c ' ok$' "$work/golden.txt")" -eq 3 ] || fail "golden check: $(cat "$work/golden.txt")"
sed -i 's/"wrap-sphere-back": "[0-9A-F]*"/"wrap-sphere-back": "0000"/' "$project/golden/hashes.json"
set +e; "$tool" golden check wrap-sphere-back --junit "$work/golden.xml" >"$work/golden.txt" 2>&1; rc=$?; set -e
[ "$rc" -eq 1 ] || fail "golden check took a changed hash (exit $rc)"
python3 - "$work/golden.xml" <<'PY' || fail "golden check's JUnit file does not say what changed"
import sys, xml.etree.ElementTree as ET
cases = ET.parse(sys.argv[1]).getroot().findall("./testsuite/testcase")
assert [c.get("name") for c in cases] == ["wrap-sphere-back"], cases
f = cases[0].find("failure")
assert f is not None and f.get("message").startswith("changed: golden 0000 now "), f.attrib
assert "wraptwin golden update wrap-sphere-back" in f.text, f.text
PY
echo "ok   wraptwin golden check: its own golden file, a changed hash fails (and says so in JUnit)"
# Its scenes as CTest tests, by technique label (the golden file is intact
# again first).
cp "$src/examples/wrap_lighting/golden/hashes.json" "$project/golden/hashes.json"
ctest --test-dir "$project/build" -L '^wrap$' >"$work/ctest.txt" || { cat "$work/ctest.txt"; fail "ctest -L wrap"; }
grep -q "100% tests passed, 0 tests failed out of 4" "$work/ctest.txt" || { cat "$work/ctest.txt"; fail "ctest -L wrap: not 4 tests"; }
echo "ok   ctest -L wrap: compare and golden check of both scenes"
"$broken" compare broken-scene --out "$work/broken" >/dev/null || fail "the broken technique's own scene"
# A twin that disagrees: compare fails, and its JUnit case carries the
# failure line and the heat map.
set +e
SHADERTWIN_TEST_BREAK=twin-differs "$broken" compare broken-scene --out "$work/differs" --junit "$work/differs.xml" >/dev/null
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "compare of a twin that differs exited $rc, not 1"
python3 - "$work/differs.xml" "$work/differs" <<'PY' || fail "compare's JUnit file does not carry the failure"
import os, sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.get("tests") == "1" and root.get("failures") == "1", root.attrib
case = root.find("./testsuite/testcase")
assert case.get("classname") == "shadertwin.broken" and case.get("name") == "broken-scene", case.attrib
f = case.find("failure")
assert "max_diff_8bit" in f.get("message"), f.attrib
heat = [l.split(": ", 1)[1] for l in f.text.splitlines() if l.startswith("heat map: ")]
assert heat and os.path.isfile(heat[0]) and heat[0].startswith(sys.argv[2]), f.text
assert "brokentwin compare broken-scene" in f.text, f.text
PY
echo "ok   a twin that differs: compare exits 1, its JUnit case has the failure line and the heat map"

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

