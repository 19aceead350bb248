#!/usr/bin/env bash
# The main job: install what is missing, build, and run `shadertwin report`
# (every built-in scene on both backends, compared; HTML in out/report/).
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/build.sh
exec ./build/shadertwin report --out out/report "$@"
