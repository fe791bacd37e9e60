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
# Side by side with Blender's default view, the region where they differ most boxed.
/usr/bin/python3 scripts/demo_sheet.py tests/scenes/cornell/cornell.exr out/cornell.png out/cornell-vs-filmic.png
echo
echo "Look at $(pwd)/out/cornell-vs-filmic.png: CG-TMO beside Blender's Filmic, where they differ boxed."
echo "Also: $(pwd)/out/cornell.png (CG-TMO) and $(pwd)/out/cornell-drago.png (global Drago)."
echo "The cgtmo program is $(pwd)/$BUILD_DIR/apps/cgtmo/cgtmo; to run it as 'cgtmo':"
echo "    export PATH=\"$(pwd)/$BUILD_DIR/apps/cgtmo:\$PATH\"      (or install it: docs/install.md)"
