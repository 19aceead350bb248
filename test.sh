#!/usr/bin/env bash
# The tests: install what is missing, build, run ctest (unit tests, live
# OSMesa comparisons, golden hashes, thread-count checks, bad input).
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j 2 "$@"
