#!/usr/bin/env bash
# The second compiler, whole (by hand): a clang++ release build in
# build-clang/, with thin LTO, must give the same golden hashes as g++ on
# every scene, and pass the unit tests. CI checks clang++ without it: the
# avx2 flavour of cli.lane_widths is clang++ at -O3 (every scene's hash),
# the sanitizer builds are clang++ at -O2 (unit tests, every scene's hash).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh clang
build=build-clang
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >&2
fi
cmake --build "$build" -j "$(nproc)" --target shadertwin unit_tests microbench >&2
"$build/tests/unit_tests" --gtest_brief=1
"$build/shadertwin" golden check >"$build/golden.out" || { grep -v ' ok$' "$build/golden.out" >&2; exit 1; }
echo "ok   clang++ $(clang++ -dumpversion): $(grep -c ' ok$' "$build/golden.out") scenes match tests/golden/hashes.json"
