#!/usr/bin/env bash
# Configures (once) and builds shadertwin into build/. With ST_LOG_DIR set
# (./run.sh), quietly: a line per step, the output in ST_LOG_DIR/build.log.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/quiet.sh
build_tree() {
  if [ ! -f build/CMakeCache.txt ]; then
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build build -j "$(nproc)"
}
run_logged build build_tree
