#!/usr/bin/env bash
# Flicker of tone-mapped sequences with and without temporal smoothing of the statistics.
# Renders a static-camera shot with Blender (the same scene, a new noise seed each frame, few
# samples: the statistics move the way they do between frames of a real noisy render), makes a
# second version of it with a transient glint in three frames, tone-maps both with global drago
# and CG-TMO at --temporal 0 and 8, and reports the frame-to-frame change of mean display
# luminance. Writes the table to stdout (docs/sequences.md quotes it).
#   bench/flicker.sh CGTMO_BINARY WORK_DIR [FRAMES] [SCENE]
set -euo pipefail
cgtmo=$(readlink -f "$1")
work=$2
frames=${3:-24}
scene=${4:-night}
repo=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work/frames"
work=$(cd "$work" && pwd)
for f in $(seq 1 "$frames"); do
  n=$(printf %04d "$f")
  [ -f "$work/frames/shot.$n.exr" ] && continue
  blender -b --factory-startup --python "$repo/scripts/blender/render_scene.py" -- --scene "$scene" \
    --out "$work/frames" --name "shot.$n" --width 240 --height 135 --samples 6 --probe-samples 6 --seed "$f" \
    >"$work/render.log" 2>&1 || { tail -20 "$work/render.log"; exit 1; }
done
# The same shot with a transient glint: frames 10 to 12 get a 3x3-pixel specular flash of
# luminance 50000 in the beauty (a firefly cluster or a glint off a moving part), the kind of
# event that moves an image maximum by orders of magnitude for a few frames.
rm -rf "$work/glint" && mkdir -p "$work/glint"
cp "$work/frames"/* "$work/glint/"
/usr/bin/python3 - "$work/glint" <<'PY'
import sys, numpy as np, OpenImageIO as oiio
for f in (10, 11, 12):
    path = f"{sys.argv[1]}/shot.{f:04d}.exr"
    buf = oiio.ImageBuf(path)
    spec = buf.spec()
    px = buf.get_pixels(oiio.FLOAT)
    names = list(spec.channelnames)
    y, x = spec.height // 3, spec.width // 2 + 5 * f
    for c in "RGB":
        px[y:y + 3, x:x + 3, names.index("ViewLayer.Combined." + c)] = 50000.0
    out = oiio.ImageBuf(spec)
    out.set_pixels(oiio.ROI(), px)
    out.write(path + ".tmp.exr")
    import os; os.replace(path + ".tmp.exr", path)
PY
echo "| shot | operator | --temporal | mean frame-to-frame change of mean display luminance (stops) | largest change (stops) |"
echo "|---|---|---|---|---|"
for shot in frames glint; do
 for op in drago cgtmo; do
  for tau in 0 8; do
    out="$work/out-$shot-$op-$tau"
    mkdir -p "$out"
    "$cgtmo" apply "$work/$shot/shot.####.exr" -o "$out/shot.####.png" --op "$op" --temporal "$tau" --force -q 2>/dev/null
    /usr/bin/python3 - "$out" "$frames" "$op" "$tau" "$shot" <<'PY'
import sys, numpy as np, OpenImageIO as oiio
out, n, op, tau, shot = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
shot = "noise only" if shot == "frames" else "noise + glint (frames 10-12)"
means = []
for f in range(1, n + 1):
    px = oiio.ImageBuf(f"{out}/shot.{f:04d}.png").get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64)
    lin = np.where(px <= 0.04045, px / 12.92, ((px + 0.055) / 1.055) ** 2.4)  # sRGB decode
    means.append(float((lin @ np.array([0.2126, 0.7152, 0.0722])).mean()))
steps = np.abs(np.diff(np.log2(np.array(means))))
print(f"| {shot} | {op} | {tau} | {steps.mean():.4f} | {steps.max():.4f} |")
PY
  done
 done
done
