#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine, builds cgtmo and tone-maps a bundled
# Blender render to a PNG you can open.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
mkdir -p out
# CG-TMO on the bundled Cornell box render (G-buffer, light groups, probe and sidecar beside it),
# with what it used and why; then the global Drago curve on the same render, to compare.
"$BUILD_DIR/apps/cgtmo/cgtmo" apply tests/scenes/cornell/cornell.exr -o out/cornell.png --op cgtmo --explain
"$BUILD_DIR/apps/cgtmo/cgtmo" apply tests/scenes/cornell/cornell.exr -o out/cornell-drago.png --op drago
echo "Open $(pwd)/out/cornell.png (CG-TMO) and $(pwd)/out/cornell-drago.png (global Drago) to see the result."
