#!/usr/bin/env bash
# shadertwin new-technique as a user meets it (issue 27): this build
# installed into a fresh prefix, the example's shaders
# (examples/wrap_lighting/glsl) made into a project by the installed tool,
# built against the install, and its compare run: it must exit 1 naming both
# twins still to write. (The tutorial's part 2, sdk.tutorial_part2, does the
# same for its shaders and then writes the twins.)
# Usage: sdk_skeleton_test.sh SOURCE_DIR BUILD_DIR CXX_COMPILER
set -euo pipefail
source "$(dirname "$0")/lib.sh"
sdk_setup "$@"
"$prefix/bin/shadertwin" new-technique wrapsk "$src/examples/wrap_lighting/glsl/wrap.vert" \
  "$src/examples/wrap_lighting/glsl/wrap.frag" --out "$work/skeleton" >"$work/skeleton.txt" ||
  { cat "$work/skeleton.txt"; fail "new-technique"; }
configure() { cmake -S "$1" -B "$2" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${@:3}"; }
start=$(date +%s)
configure "$work/skeleton" "$work/skeleton/build" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure the skeleton"; }
cmake --build "$work/skeleton/build" -j 2 >"$work/build.log" 2>&1 || { tail -40 "$work/build.log"; fail "build the skeleton"; }
set +e; "$work/skeleton/build/wrapsktwin" compare wrapsk-first --out "$work/skeleton/out" >"$work/compare.txt" 2>&1; rc=$?; set -e
[ "$rc" -eq 1 ] || { cat "$work/compare.txt"; fail "the skeleton's compare: exit $rc, expected 1"; }
grep -q "twin of wrapsk.vert not written yet: write run() in kernels/wrapsk_vert.cpp" "$work/compare.txt" &&
  grep -q "twin of wrapsk.frag not written yet: write main() in kernels/wrapsk_frag.cpp" "$work/compare.txt" ||
  { cat "$work/compare.txt"; fail "the skeleton's compare does not say what is left to write"; }
[ -s "$work/skeleton/out/wrapsk-first.gl.png" ] || fail "the skeleton's scene was not drawn"
echo "ok   new-technique: the example's shaders as a project built in $(( $(date +%s) - start )) s; compare exits 1: $(grep -c 'not written yet' "$work/compare.txt") twins to write"

# The project's twins against its GLSL, checked on every run (issue 29): the
# shaders are read at run time, so an edit to them alone, which GL would
# link happily, must be refused with one line naming both sides (exit 2,
# nothing written), before anything renders.
proj="$work/skeleton"
cp "$proj/glsl/wrapsk.vert" "$work/wrapsk.vert.orig"
cp "$proj/glsl/wrapsk.frag" "$work/wrapsk.frag.orig"
sed -i 's/v_normal/v_norm/g' "$proj/glsl/wrapsk.vert" "$proj/glsl/wrapsk.frag"
expect_refused "a varying renamed in both shaders" "names slot 0 'v_normal', which wrapsk.frag does not declare as an input" \
  "$proj/build/wrapsktwin" compare wrapsk-first
cp "$work/wrapsk.vert.orig" "$proj/glsl/wrapsk.vert"
cp "$work/wrapsk.frag.orig" "$proj/glsl/wrapsk.frag"
sed -i 's/layout(location = 0) in vec4 v_normal/layout(location = 1) in vec4 v_normal/' "$proj/glsl/wrapsk.frag"
sed -i 's/layout(location = 0) out vec4 v_normal/layout(location = 1) out vec4 v_normal/' "$proj/glsl/wrapsk.vert"
expect_refused "a varying moved to another location" "holds 'v_normal' in slot 0; wrapsk.frag declares it at location 1" \
  "$proj/build/wrapsktwin" compare wrapsk-first
cp "$work/wrapsk.vert.orig" "$proj/glsl/wrapsk.vert"
cp "$work/wrapsk.frag.orig" "$proj/glsl/wrapsk.frag"
sed -i 's/uniform float wrap; /uniform int wrap; /' "$proj/glsl/wrapsk.frag"
expect_refused "a uniform's type changed in the shader" "uniform 'wrap' is an int in wrapsk.frag, and the scene sets a float" \
  "$proj/build/wrapsktwin" compare wrapsk-first
# restore: put both shaders back as new-technique wrote them.
restore() { cp "$work/wrapsk.vert.orig" "$proj/glsl/wrapsk.vert"; cp "$work/wrapsk.frag.orig" "$proj/glsl/wrapsk.frag"; }
restore
sed -i 's/uniform float wrap; /uniform float wrapping; /; s/(n_dot_l + wrap)/(n_dot_l + wrapping)/; s/(1.0 + wrap)/(1.0 + wrapping)/' \
  "$proj/glsl/wrapsk.frag"
expect_refused "a uniform renamed in the shader" "the scene sets uniform 'wrap', which neither wrapsk.vert nor wrapsk.frag declares" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
sed -i 's/^uniform vec3 albedo;/uniform vec3 albedo;\nuniform float gain;/; s/frag_colour = vec4(colour, 1.0);/frag_colour = vec4(colour * gain, 1.0);/' \
  "$proj/glsl/wrapsk.frag"
expect_refused "a uniform the scene never sets" "uniform 'gain' (float in wrapsk.frag, active in the program) is never set" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
sed -i 's/layout(location = 0) in vec4 v_normal/layout(location = 0) flat in vec4 v_normal/' "$proj/glsl/wrapsk.frag"
sed -i 's/layout(location = 0) out vec4 v_normal/layout(location = 0) flat out vec4 v_normal/' "$proj/glsl/wrapsk.vert"
expect_refused "an input made flat" "'v_normal' is flat in wrapsk.frag, and the twin of wrapsk.frag's interpolations() has slot 0 smooth" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
sed -i 's/in vec4 v_normal/in vec2 v_normal/; s/normalize(v_normal.xyz)/normalize(vec3(v_normal, 1.0))/' "$proj/glsl/wrapsk.frag"
sed -i 's/out vec4 v_normal/out vec2 v_normal/; s/v_normal = normal;/v_normal = normal.xy;/' "$proj/glsl/wrapsk.vert"
expect_refused "an input narrowed" "the twin of wrapsk.frag reads component w of slot 0, 'v_normal', a vec2 in wrapsk.frag" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
sed -i 's/^layout(location = 0) out vec4 frag_colour;/layout(location = 0) out vec4 frag_colour;\nlayout(location = 1) out vec4 extra;/' \
  "$proj/glsl/wrapsk.frag"
expect_refused "an output added" "wrapsk.frag declares outputs frag_colour at 0, extra at 1, and the pass draws into 1 target" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
sed -i 's/in vec4 normal;/in vec4 normal_in;/; s/v_normal = normal;/v_normal = normal_in;/' "$proj/glsl/wrapsk.vert"
expect_refused "an attribute renamed" "the draw names attribute 1 'normal', which wrapsk.vert does not declare as an input" \
  "$proj/build/wrapsktwin" compare wrapsk-first
restore
