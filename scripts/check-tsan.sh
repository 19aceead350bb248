#!/usr/bin/env bash
# The ThreadSanitizer check (CI, after ./test.sh): a clang++ build with
# -fsanitize=thread in build-tsan/ runs the worker pool's and the Monte
# Carlo tracer's unit tests and tests/sanitizers/threads.sh (the CPU
# pipeline at 1/2/3/8 threads, the tracer at 1 and 8). llvmpipe is not run
# under TSan: Mesa is not built with it, and its own synchronisation would
# be reported falsely. See docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh clang
build=build-tsan
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADERTWIN_SANITIZE=thread >&2
fi
cmake --build "$build" -j "$(nproc)" --target shadertwin thread_unit_tests >&2
source scripts/sanitizer-env.sh
"$build/tests/thread_unit_tests" --gtest_brief=1
bash tests/sanitizers/threads.sh "$build/shadertwin"
