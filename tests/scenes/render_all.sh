#!/bin/sh
# Regenerates every committed render in tests/scenes/ (see README.md for times and figures).
# Run from the repository root: sh tests/scenes/render_all.sh [SCENE...]
# Renders are not bit-reproducible (docs/platform.md): re-running changes the noise, not the scenes.
set -e
R="blender -b --factory-startup --python scripts/blender/render_scene.py --"
run() {
  name=$1; shift
  if [ -n "$ONLY" ] && ! echo " $ONLY " | grep -q " $name "; then return 0; fi
  echo "== $name"
  $R "$@"
}
ONLY="$*"
run cornell        --scene cornell        --out tests/scenes/cornell        --width 480 --height 270 --samples 256
run two-rooms      --scene two-rooms      --out tests/scenes/two-rooms      --width 480 --height 270 --samples 256
run sun-window     --scene sun-window     --out tests/scenes/sun-window     --width 480 --height 270 --samples 256
run night          --scene night          --out tests/scenes/night          --width 480 --height 270 --samples 128
run relief         --scene relief         --out tests/scenes/relief         --width 480 --height 270 --samples 128
run colored-lights --scene colored-lights --out tests/scenes/colored-lights --width 480 --height 270 --samples 128
run lit-box        --scene lit-box        --out tests/scenes/lit-box        --width 480 --height 270 --samples 64
run dark-doorway   --scene dark-doorway   --out tests/scenes/dark-doorway   --width 480 --height 270 --samples 64
run bench          --scene cornell        --out tests/scenes/bench --name cornell-1080p --width 1920 --height 1080 --samples 16 --no-probe --codec PXR24
