#!/usr/bin/env bash
# Builds the installable Blender add-on: $BUILD_DIR/cgtmo_addon.zip (default BUILD_DIR=build).
# Configures the build folder against /usr/bin/python3 (the Python that Blender 3.4 embeds,
# docs/platform.md), builds the `cgtmo` Python module, and packs it with plugins/blender/cgtmo_addon/ and
# the scene generator's shared modules (scripts/blender/). Install the zip in Blender with
# Edit > Preferences > Add-ons > Install..., or see docs/plugins.md for the command line.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
generator=()
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B "$BUILD_DIR" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCGTMO_BUILD_PYTHON=ON >/dev/null
cmake --build "$BUILD_DIR" --target cgtmo_blender_addon --parallel "$(nproc)"
echo "add-on: $BUILD_DIR/cgtmo_addon.zip"
