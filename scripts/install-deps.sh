#!/usr/bin/env bash
# Installs the Debian packages shadertwin builds with, when any is missing.
# Skips apt entirely when everything is already there. With the argument
# `clang`, also what the sanitizer, fuzzing and second-compiler checks need
# (scripts/check-*.sh): clang++, its sanitizer and libFuzzer runtimes, and
# llvm-symbolizer for readable stack traces.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libglm-dev libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev nettle-dev
  libgtest-dev libbenchmark-dev
  mesa-common-dev libosmesa6-dev libegl-dev libegl-mesa0  # GL headers; the two GL platforms (gl/gl_context.h)
  nlohmann-json3-dev libcli11-dev libkissfft-dev
  chromium  # cli.report_page opens the report in headless Chromium, as a user would
)
if [ "${1:-}" = clang ]; then
  packages+=(clang libclang-rt-14-dev llvm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi
echo "installing: ${missing[*]}" >&2
source "$(dirname "$0")/quiet.sh"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
install_packages() {
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
run_logged install install_packages
