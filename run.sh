#!/usr/bin/env bash
# The main job: install what is missing, build, and run `shadertwin report`
# (every built-in scene on both backends, compared and timed; the page in
# out/report/index.html, the tables in out/report/summary.md). It prints a
# few lines: the install and the build each say what they did, with the
# full log in out/logs/ (shown in part when a step fails), and the report
# ends with what it found (`report --brief`).
set -euo pipefail
cd "$(dirname "$0")"
export ST_LOG_DIR="$PWD/out/logs"
./scripts/install-deps.sh
./scripts/build.sh
exec ./build/shadertwin report --out out/report --brief "$@"
