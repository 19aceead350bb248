#!/usr/bin/env bash
# The tests: install what is missing, build, run ctest (unit tests, live
# OSMesa comparisons, golden hashes, thread-count checks, bad input, the
# installed package). The per-scene tests (label `scene`: one process per
# scene, for `ctest -L <technique>` and sharding) repeat what
# cli.compare_builtin and cli.golden check in one process each, and would
# add minutes here; cli.ctest_labels runs one technique's of them. Label
# `long` (cli.lane_widths: two more builds, four minutes; sdk.lto: a user's
# tool linked with LTO; sdk.tutorial_part2 and sdk.skeleton: new-technique's
# projects built against the install; cli.threads: every golden hash at 1, 3
# and 8 threads) runs in CI right after this script (.ci/run);
# `ctest --test-dir build -L long` runs it here.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j 2 -LE "^(scene|long)$" "$@"
