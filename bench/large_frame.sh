#!/usr/bin/env bash
# CG-TMO on an 8K (7680x4320) multilayer frame: time and peak memory.
# The frame is the committed 1920x1080 bench render with every pass repeated 4x4 (nearest
# neighbour, so the G-buffer stays a real render's) and a sidecar for the new resolution. Prints
# wall time, peak resident memory (/usr/bin/time -v), the float32 size of the channels CG-TMO reads
# (beauty RGBA, depth, position, normal, albedo, one RGB per light group) and their ratio.
#   bench/large_frame.sh CGTMO_BINARY WORK_DIR [OPERATOR_ARGS...]
set -euo pipefail
cgtmo=$(readlink -f "$1")
work=$2
shift 2
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--op cgtmo)
repo=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
src="$repo/tests/scenes/bench/cornell-1080p"
big="$work/cornell-8k"
if [ ! -f "$big.exr" ]; then
  /usr/bin/python3 - "$src" "$big" <<'PY'
import json, sys, numpy as np, OpenImageIO as oiio
src, big = sys.argv[1], sys.argv[2]
inp = oiio.ImageInput.open(src + ".exr")
spec = inp.spec()
px = inp.read_image(oiio.FLOAT)
inp.close()
px = np.repeat(np.repeat(px, 4, axis=0), 4, axis=1)
out_spec = oiio.ImageSpec(spec.width * 4, spec.height * 4, spec.nchannels, oiio.FLOAT)
out_spec.channelnames = spec.channelnames
out_spec.channelformats = spec.channelformats
out_spec.attribute("compression", "zip")
out = oiio.ImageOutput.create(big + ".exr")
assert out.open(big + ".exr", out_spec), oiio.geterror()
assert out.write_image(px), out.geterror()
out.close()
side = json.load(open(src + ".json"))
side["camera"]["resolution"] = [spec.width * 4, spec.height * 4]
if "pixel_footprint_at_1m" in side["camera"]:
    side["camera"]["pixel_footprint_at_1m"] /= 4.0
json.dump(side, open(big + ".json", "w"), indent=1)
PY
fi
read -r w h nread < <(/usr/bin/python3 - "$big.exr" <<'PY'
import sys, OpenImageIO as oiio
s = oiio.ImageInput.open(sys.argv[1]).spec()
n = [c for c in s.channelnames if any(c.startswith("ViewLayer." + p + ".") for p in
     ("Combined", "Depth", "Position", "Normal", "DiffCol")) or c.split(".")[1].startswith("Combined_")]
print(s.width, s.height, len(n))
PY
)
/usr/bin/time -v "$cgtmo" apply "$big.exr" -o "$work/out.png" "${args[@]}" -q 2> "$work/time.log" || { tail -5 "$work/time.log"; exit 1; }
rss_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.log")
wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$work/time.log")
read_mb=$(( w * h * nread * 4 / 1048576 ))
echo "frame ${w}x${h}; ${args[*]}; channels read: $nread (float32 ${read_mb} MB)"
echo "wall ${wall}; peak RSS $(( rss_kb / 1024 )) MB; ratio to channels read $(awk "BEGIN{printf \"%.2f\", $rss_kb / 1024 / $read_mb}")"
