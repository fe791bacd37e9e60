#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine, builds cgtmo and tone-maps a bundled
# Blender render to a PNG you can open.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
mkdir -p out
input=tests/scenes/cornell/cornell.exr
[ -f "$input" ] || input=tests/scenes/cornell.exr
"$BUILD_DIR/apps/cgtmo/cgtmo" apply "$input" -o out/cornell.png --op drago
echo "Open $(pwd)/out/cornell.png to see the result."
