#!/bin/sh
# Renders every scene tiny with scripts/blender/render_scene.py (cornell at 64x36, 4 samples, the
# others at 32x18, 1 sample) into OUT and reads each back with the scene reader (CHECKER).
# Usage: render_roundtrip.sh SOURCE_DIR OUT CHECKER. Exit 77 (skipped) when blender is missing.
set -u
src=$1 out=$2 checker=$3
if ! command -v blender >/dev/null 2>&1; then
  echo "SKIP: blender is not installed (scripts/install-deps.sh installs it); the generator round trip needs it"
  exit 77
fi
rm -rf "$out" && mkdir -p "$out" || exit 1
render() {
  scene=$1; shift
  if ! blender -b --factory-startup --python "$src/scripts/blender/render_scene.py" -- \
       --scene "$scene" --out "$out" "$@" > "$out/$scene.log" 2>&1; then
    echo "FAIL: blender could not render $scene; last lines of $out/$scene.log:"
    tail -n 15 "$out/$scene.log"
    exit 1
  fi
}
render cornell --width 64 --height 36 --samples 4 --probe-samples 4
for s in two-rooms sun-window night relief colored-lights lit-box dark-doorway; do
  render "$s" --width 32 --height 18 --samples 1 --probe-samples 1
done
"$checker" "$out" cornell:64x36 two-rooms:32x18 sun-window:32x18 night:32x18 relief:32x18 colored-lights:32x18 lit-box:32x18 \
  dark-doorway:32x18
