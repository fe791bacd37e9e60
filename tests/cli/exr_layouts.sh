#!/usr/bin/env bash
# OpenEXR layouts through the tool (docs/exr-inputs.md): overscan and auto-cropped data windows
# and --window, a multi-part file whose depth part is smaller than the beauty, a stereo file and
# --exr-view, --pass, the scene operators' --probe/--sidecar (missing or foreign: a warning
# and exit 0), an alpha that covers nothing, and the beauty by other applications' names. Inputs are written here with OpenImageIO's Python module.
# Usage: exr_layouts.sh CGTMO_BINARY WORK_DIR   (exit 0 pass, 1 fail)
set -u
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
py=/usr/bin/python3
failed=0
fail() { echo "FAIL $*"; failed=1; }

# run CASE RC CMD...: CMD exits RC; its stdout and stderr are kept as CASE.out and CASE.err.
run() {
  local name=$1 rc=$2
  shift 2
  bounded 60 "$@" >"$work/$name.out" 2>"$work/$name.err" </dev/null
  local got=$?
  if [ "$got" -eq "$rc" ]; then echo "ok   $name"; else
    fail "$name: exit $got (want $rc)"
    sed 's/^/     /' "$work/$name.err" | head -5
  fi
}
# has CASE STREAM TEXT: the case's stdout (out) or stderr (err) holds TEXT.
has() { grep -qF -- "$3" "$work/$1.$2" || { fail "$1: $2 lacks '$3':"; sed 's/^/     /' "$work/$1.$2" | head -8; }; }
lines() { [ "$(wc -l <"$work/$1.err")" -eq "$2" ] || fail "$1: stderr has $(wc -l <"$work/$1.err") lines, want $2"; }
size_of() { "$py" -c "import OpenImageIO as o,sys; s=o.ImageInput.open(sys.argv[1]).spec(); print(f'{s.width}x{s.height}')" "$1"; }

"$py" - "$work" <<'PYEOF' || { echo "FAIL making inputs"; exit 1; }
import os, sys
import numpy as np
import OpenImageIO as oiio
w = sys.argv[1]

def spec(width, height, names, x=0, y=0, full=None):
    s = oiio.ImageSpec(width, height, len(names), "float")
    s.channelnames = names
    s.x, s.y = x, y
    fx, fy, fw, fh = full if full else (x, y, width, height)
    s.full_x, s.full_y, s.full_width, s.full_height = fx, fy, fw, fh
    return s

def write(name, specs, pixels):
    path = os.path.join(w, name)
    out = oiio.ImageOutput.create(path)
    assert out.open(path, specs), out.geterror()
    for i, (s, p) in enumerate(zip(specs, pixels)):
        if i: assert out.open(path, s, "AppendSubimage"), out.geterror()
        assert out.write_image(p), out.geterror()
    out.close()

rgb = ("R", "G", "B")
# Overscan: data (-2,-1) 8x4 around a 4x2 display window.
write("over.exr", [spec(8, 4, rgb, -2, -1, (0, 0, 4, 2))], [np.full((4, 8, 3), 0.5, np.float32)])
# A two-part render: beauty 16x8 with normals, a depth part covering only (4,2) 8x4.
beauty = spec(16, 8, rgb + ("N.x", "N.y", "N.z"))
beauty.attribute("name", "beauty")
depth = spec(8, 4, ("Z",), 4, 2, (0, 0, 16, 8))
depth.attribute("name", "depth")
b = np.full((8, 16, 6), 0.5, np.float32)
b[..., 5] = 1.0
write("parts.exr", [beauty, depth], [b, np.full((4, 8, 1), 3.0, np.float32)])
# Stereo, one part: left unprefixed (0.25), right prefixed (2.0).
st = spec(4, 2, rgb + ("right.R", "right.G", "right.B"))
st.attribute("multiView", oiio.TypeDesc("string[2]"), ("left", "right"))
p = np.empty((2, 4, 6), np.float32)
p[..., :3], p[..., 3:] = 0.25, 2.0
write("stereo.exr", [st], [p])
# Names no automatic mapping knows, for --pass.
write("odd.exr", [spec(4, 2, rgb + ("nrm.x", "nrm.y", "nrm.z"))], [np.full((2, 4, 6), 0.5, np.float32)])
# An alpha of 0 everywhere over colour (OpenEXR's Carrots.exr has one).
write("no_cover.exr", [spec(4, 2, rgb + ("A",))], [np.concatenate([np.full((2, 4, 3), 0.5, np.float32), np.zeros((2, 4, 1), np.float32)], 2)])
# Nuke's rgba layer beside an albedo AOV; AOVs alone.
write("nuke.exr", [spec(4, 2, ("diffuse.R", "diffuse.G", "diffuse.B", "rgba.red", "rgba.green", "rgba.blue"))],
      [np.full((2, 4, 6), 0.5, np.float32)])
write("aovs.exr", [spec(4, 2, ("diffuse.R", "diffuse.G", "diffuse.B", "specular.R", "specular.G", "specular.B"))],
      [np.full((2, 4, 6), 0.5, np.float32)])
PYEOF

# Windows.
run over_display 0 "$cgtmo" apply "$work/over.exr" -o "$work/over_display.exr" --op reinhard --no-display -q
[ "$(size_of "$work/over_display.exr")" = 4x2 ] || fail "over_display: output is $(size_of "$work/over_display.exr"), want 4x2"
run over_data 0 "$cgtmo" apply "$work/over.exr" -o "$work/over_data.exr" --op reinhard --no-display -q --window data
[ "$(size_of "$work/over_data.exr")" = 8x4 ] || fail "over_data: output is $(size_of "$work/over_data.exr"), want 8x4"
run over_bad_window 2 "$cgtmo" apply "$work/over.exr" -o "$work/x.png" --window crop
has over_bad_window err "--window 'crop': use display or data"
lines over_bad_window 1
run over_info 0 "$cgtmo" info "$work/over.exr"
has over_info out "part 0: data 8x4 at (-2,-1), display 4x2 at (0,0)"
has over_info out "read: display window, 4x2 at (0,0)"

# A depth part smaller than the beauty: it used to be refused; outside it is background.
run parts_info 0 "$cgtmo" info "$work/parts.exr"
has parts_info out "background 75.00 % (96 px)"
run parts_cgtmo 0 "$cgtmo" apply "$work/parts.exr" -o "$work/parts.png" --op cgtmo -q
# No probe, no sidecar beside it: one warning line each, naming the file looked for.
has parts_cgtmo err "no adaptation probe ('$work/parts.probe.exr' does not exist): Lw_a is the image's"
has parts_cgtmo err "no sidecar ('$work/parts.json' does not exist) and the render has no light-group passes: Lw_max is the image maximum"

# Companions named on the command line.
echo '{"generator": "another tool", "frames": [1, 2]}' >"$work/foreign.json"
run sidecar_foreign 0 "$cgtmo" apply "$work/parts.exr" -o "$work/p1.png" --op cgtmo -q --sidecar "$work/foreign.json"
has sidecar_foreign err "no sidecar ('$work/foreign.json' is JSON of another kind, ignored) and the render"
run sidecar_missing 0 "$cgtmo" apply "$work/parts.exr" -o "$work/p2.png" --op cgtmo -q --sidecar "$work/nothere.json" --probe "$work/nothere.exr"
has sidecar_missing err "no sidecar ('$work/nothere.json' does not exist)"
has sidecar_missing err "no adaptation probe ('$work/nothere.exr' does not exist)"
echo '{"camera": ' >"$work/broken.json"
run sidecar_broken 1 "$cgtmo" apply "$work/parts.exr" -o "$work/p3.png" --op cgtmo -q --sidecar "$work/broken.json"
has sidecar_broken err "broken.json"
run sidecar_global_op 2 "$cgtmo" apply "$work/parts.exr" -o "$work/p4.png" --op drago --sidecar "$work/foreign.json"
has sidecar_global_op err "--probe and --sidecar are read by the scene operators"
run sidecar_sequence 2 "$cgtmo" apply "$work/shot.####.exr" -o "$work/out.####.png" --op cgtmo --sidecar "$work/foreign.json"
has sidecar_sequence err "not for a sequence"
lines sidecar_sequence 1

# Views.
run view_default 0 "$cgtmo" apply "$work/stereo.exr" -o "$work/left.exr" --op reinhard --no-display -q
run view_right 0 "$cgtmo" apply "$work/stereo.exr" -o "$work/right.exr" --op reinhard --no-display -q --exr-view right
"$py" - "$work" <<'PYEOF' || fail "views: left and right outputs are not each view's (reinhard of 0.25 and of 2)"
import sys, OpenImageIO as oiio
w = sys.argv[1]
def first(name):
    return oiio.ImageBuf(w + "/" + name).getpixel(0, 0)[0]
# Reinhard: x / (1 + x).
assert abs(first("left.exr") - 0.25 / 1.25) < 1e-4, first("left.exr")
assert abs(first("right.exr") - 2.0 / 3.0) < 1e-4, first("right.exr")
PYEOF
run view_unknown 1 "$cgtmo" apply "$work/stereo.exr" -o "$work/c.png" --exr-view centre
has view_unknown err "no view 'centre' (views: left, right)"
lines view_unknown 1
run view_info 0 "$cgtmo" info "$work/stereo.exr" --exr-view right
has view_info out "views: left right (read)"

# --pass.
run pass_info 0 "$cgtmo" info "$work/odd.exr" --pass normal=nrm
has pass_info out "nrm.x,nrm.y,nrm.z (--pass)"
run pass_missing 1 "$cgtmo" apply "$work/odd.exr" -o "$work/o.png" --op cgtmo --pass normal=nothere
has pass_missing err "--pass normal=nothere: no channels nothere.X,Y,Z or nothere.R,G,B"
lines pass_missing 1
run pass_bad_role 2 "$cgtmo" info "$work/odd.exr" --pass colour=nrm
has pass_bad_role err "use ROLE=LAYER"

# Alpha: one covering nothing is dropped, with one warning on stderr.
run alpha_none 0 "$cgtmo" apply "$work/no_cover.exr" -o "$work/no_cover.png" --op reinhard -q
has alpha_none err "no_cover.exr: alpha is 0 at every pixel while the colour is not: alpha dropped, the output is opaque"
lines alpha_none 1
[ "$("$py" -c "import OpenImageIO as o,sys; print(o.ImageInput.open(sys.argv[1]).spec().nchannels)" "$work/no_cover.png")" = 3 ] ||
  fail "alpha_none: the output is not RGB"

# The beauty by name: Nuke's rgba over an AOV; AOVs alone refused in one line, then --layer.
run names_nuke 0 "$cgtmo" info "$work/nuke.exr"
has names_nuke out "beauty: rgba"
run names_aovs 1 "$cgtmo" apply "$work/aovs.exr" -o "$work/aovs.png" --op reinhard
has names_aovs err "name it with --layer (RGB layers: diffuse, specular;"
lines names_aovs 1
run names_layer 0 "$cgtmo" apply "$work/aovs.exr" -o "$work/aovs.png" --op reinhard -q --layer specular

exit $failed
