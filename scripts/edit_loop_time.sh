#!/usr/bin/env bash
# A user's edit loop, timed (issue 25): this build installed into a fresh
# prefix, examples/wrap_lighting configured against it as a user's project,
# built once; then ROUNDS times an edit of one twin file (a comment line
# added to kernels/wrap_frag.cpp) and `cmake --build`, each rebuild timed.
# Prints every round and the median. docs/adding-a-technique.md quotes it.
# Usage: scripts/edit_loop_time.sh [BUILD_TYPE [ROUNDS [-DSHADERTWIN_LTO=...]]]
#   (default RelWithDebInfo, 5 rounds, the build type's default LTO)
set -euo pipefail
cd "$(dirname "$0")/.."
type="${1:-RelWithDebInfo}"
rounds="${2:-5}"
extra=("${@:3}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install build --prefix "$work/prefix" >/dev/null
cp -r examples/wrap_lighting "$work/project"
rm -rf "$work/project/build"
cmake -S "$work/project" -B "$work/project/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE="$type" \
  "${extra[@]}" >/dev/null
start=$SECONDS
cmake --build "$work/project/build" -j "$(nproc)" >/dev/null
echo "first build ($type ${extra[*]}): $(( SECONDS - start )) s"
times=()
for i in $(seq "$rounds"); do
  echo "// edit $i" >>"$work/project/kernels/wrap_frag.cpp"
  t0=$(date +%s.%N)
  cmake --build "$work/project/build" -j "$(nproc)" >/dev/null
  t1=$(date +%s.%N)
  times+=("$(echo "$t1 - $t0" | bc)")
  echo "rebuild after an edit of one twin, round $i: ${times[-1]} s"
done
printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {printf "median of %d: %.2f s\n", NR, (NR % 2 ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2)}'
