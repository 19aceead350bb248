#!/usr/bin/env bash
# The AddressSanitizer + UndefinedBehaviorSanitizer check (CI, after
# ./test.sh): a clang++ build with both sanitizers and the libFuzzer targets
# in build-asan/, the test suite under it (every UB finding and every leak
# of ours fails a test; Mesa's leaks: tests/sanitizers/lsan.supp) but the
# per-scene tests (cli.compare_builtin runs every scene), the long ones
# (they compare hashes across builds, which a sanitizer adds nothing to;
# .ci/run runs them on the release build) and the sdk ones (they build a
# user's project against the install again, 70 s of test time under ASan,
# to run library code the cli tests already run here; ./test.sh runs them
# on the release build), then a short run of each fuzz target
# (FUZZ_SECONDS each, default 20).
# See docs/reliability.md.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh clang
build=build-asan
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSHADERTWIN_SANITIZE=address,undefined -DSHADERTWIN_FUZZ=ON >&2
fi
# (microbench too: no test runs it, and this is where CI compiles it.)
cmake --build "$build" -j "$(nproc)" --target all microbench >&2
source scripts/sanitizer-env.sh
ctest --test-dir "$build" --output-on-failure -j 2 -LE "^(scene|long|sdk)$" "$@"
fuzz/run.sh "$build" "${FUZZ_SECONDS:-20}"
