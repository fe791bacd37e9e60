#!/usr/bin/env bash
# Messages that help a newcomer: did-you-mean for commands, operators, displays, views, options
# and colour spaces; a second positional that is an image names -o; a frame pattern with the
# wrong padding names the right one; a sequence's warnings reach the terminal and --json,
# grouped over its frames; the 'wrote' line prints Lw_max and Lw_a once; long work shows
# progress; `apply --help` starts with the synopsis and examples.
#   messages.sh CGTMO_BINARY INPUTS_DIR WORK_DIR
set -uo pipefail
cgtmo=$(readlink -f "$1")
inputs=$(readlink -f "$2")
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
# usage NAME EXPECTED_TEXT ARGS...: exit 2 and one line on stderr holding EXPECTED_TEXT.
usage() {
  local name=$1 text=$2
  shift 2
  "$cgtmo" "$@" >out.txt 2>err.txt
  local rc=$?
  check "$name" '[ $rc -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -qF -- "$text" err.txt || { cat err.txt; false; }'
}
hdr=$inputs/hdr.exr

usage "a typo of a command" "unknown command 'aply' (did you mean 'apply'?)" aply
usage "a family of operators" "unknown operator 'aces' (did you mean 'aces-hill' or 'aces-narkowicz'?)" apply "$hdr" -o x.png --op aces
usage "a display named in part" "display 'P3' is not in the OCIO config (did you mean 'Display P3'?)" apply "$hdr" -o x.png --op agx --display P3
usage "a view in the wrong case" "(did you mean 'Standard'?)" apply "$hdr" -o x.png --op agx --view standard
usage "an option typo" "unknown option '--opp' (did you mean '--op'?)" apply "$hdr" --opp agx -o x.png
usage "an option typo with a value" "unknown option '--exposur' (did you mean '--exposure'?)" apply "$hdr" -o x.png --exposur=1
usage "a colour space typo" "(did you mean 'Linear Rec.709'?)" apply "$hdr" -o x.png --op agx --colorspace "linear rec.709 "
usage "an output given as a positional" "'x.png' looks like the output: name it with -o (-o x.png)" apply "$hdr" x.png
usage "a filter typo" "'fats' (did you mean 'fast'?)" apply "$hdr" -o x.png --op cgtmo -p filter=fats
usage "a parameter typo" "has no parameter 'stop' (did you mean 'stops'?)" apply "$hdr" -o x.png --op cgtmo -p stop=4
check "nothing was written by the refused commands" '[ ! -e x.png ]'

# A frame pattern whose padding is not the files'.
mkdir -p seq out
for f in 1 2 3; do cp "$hdr" "seq/shot.000$f.exr"; done
"$cgtmo" apply 'seq/shot.#.exr' -o 'out/o.#.png' --op agx >out.txt 2>err.txt
check "a '#' pattern beside 4-digit files names '####' (exit 1, one line)" \
  '[ $? -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -qF "4-digit numbers, as in '"'"'shot.0001.exr'"'"': use '"'"'seq/shot.####.exr'"'"'" err.txt'

# A sequence's warnings, grouped: the NaN pixel and the missing probe and sidecar of every frame.
"$cgtmo" apply 'seq/shot.####.exr' -o 'out/o.####.png' --op cgtmo -q >out.txt 2>err.txt
rc=$?
check "sequence: exit 0" '[ $rc -eq 0 ]'
check "sequence: the non-finite warning once for frames 1-3" \
  '[ "$(grep -c "NaN" err.txt)" -eq 1 ] && grep -q "^cgtmo apply: warning: frames 1-3: .*NaN" err.txt || { cat err.txt; false; }'
check "sequence: the missing probe once for frames 1-3, named by the pattern" \
  'grep -q "^cgtmo apply: warning: frames 1-3: .*probe.*shot\.####\.probe\.exr" err.txt || { cat err.txt; false; }'
"$cgtmo" apply "$hdr" -o one.png --op cgtmo -q 2>one.err
check "a single file warns the same things (probe, NaN)" 'grep -q "probe" one.err && grep -q "NaN" one.err'
"$cgtmo" apply 'seq/shot.####.exr' -o 'out/j.####.png' --op cgtmo --json >out.json 2>err.txt
check "sequence --json: the warnings with their frames" \
  '/usr/bin/python3 -c "
import json, sys
j = json.load(open(\"out.json\"))
w = j[\"warnings\"]
assert any(x[\"frames\"] == \"1-3\" and \"NaN\" in x[\"message\"] for x in w), w
assert any(x[\"frames\"] == \"1-3\" and \"shot.####.probe.exr\" in x[\"message\"] for x in w), w
"'

# The wrote line: Lw_max and Lw_a as used, not the parameters' 0 ("from the scene").
"$cgtmo" apply "$hdr" -o wrote.png --op cgtmo >out.txt 2>/dev/null
check "wrote line: no lw_a=0 or lw_max=0, the values used once" \
  'grep -q "^wrote wrote.png" out.txt && ! grep -q "lw_a=\|lw_max=" out.txt && grep -q "Lw_max [0-9.e+-]*, Lw_a [0-9.e+-]*" out.txt || { cat out.txt; false; }'

# Progress off a terminal: the temporal pre-pass counts its frames.
"$cgtmo" apply 'seq/shot.####.exr' -o 'out/d.####.png' --op drago >out.txt 2>err.txt
check "temporal pre-pass: one progress line per frame measured, ending at 3/3" \
  '[ "$(grep -c "statistics for temporal smoothing: frames measured" out.txt)" -eq 3 ] && grep -q "frames measured (3/3)" out.txt || { cat out.txt; false; }'

# eval --scenes: each scene's methods as stages on stderr; stdout holds the report alone.
# TMQI needs 161 pixels each way: the input, scaled up.
mkdir -p scenes/tiny && oiiotool "$hdr" --resize 256x176 -o scenes/tiny/tiny.exr
"$cgtmo" eval --scenes scenes >report.md 2>err.txt
check "eval --scenes: exit 0, a stage line per method on stderr" \
  '[ $? -eq 0 ] && grep -q "scene 1/1 scenes/tiny/tiny.exr: cgtmo-exact (4/12)" err.txt && grep -q "output modes (12/12)" err.txt || { cat err.txt; false; }'
check "eval --scenes: stdout is the report" '! grep -q "scene 1/1" report.md && grep -q "tiny" report.md'

# One search order for the companions: NAME.probe.exr, else the sidecar's probe.file.
repo=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p comp
for ext in exr json probe.exr; do cp "$repo/tests/scenes/cornell/cornell.$ext" "comp/render.$ext"; done
lw_a() { /usr/bin/python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['scene_statistics']['lw_a_source'])" "$1"; }
"$cgtmo" apply "$repo/tests/scenes/cornell/cornell.exr" -o c.png --op cgtmo --json >cornell.json 2>/dev/null
"$cgtmo" apply comp/render.exr -o r.png --op cgtmo --json >render.json 2>err.txt
check "a render copied with its companions keeps its probe (render.probe.exr, sidecar says cornell.probe.exr)" \
  '[ "$(lw_a render.json)" = "$(lw_a cornell.json)" ] && ! grep -q "probe" err.txt || { lw_a render.json; cat err.txt; false; }'
mv comp/render.probe.exr comp/cornell.probe.exr
"$cgtmo" apply comp/render.exr -o r.png --op cgtmo --json >render2.json 2>err.txt
check "no NAME.probe.exr: the probe the sidecar names is read" \
  '[ "$(lw_a render2.json)" = "$(lw_a cornell.json)" ] && ! grep -q "probe" err.txt || { cat err.txt; false; }'
mv comp/cornell.probe.exr comp/elsewhere.exr
"$cgtmo" apply comp/render.exr -o r.png --op cgtmo >out.txt 2>err.txt
check "neither: one warning naming both places" \
  'grep -qF "no adaptation probe ('"'"'comp/cornell.probe.exr'"'"' does not exist, nor '"'"'comp/render.probe.exr'"'"')" err.txt || { cat err.txt; false; }'
"$cgtmo" apply comp/render.exr -o r.png --op cgtmo --explain >out.txt 2>/dev/null
check "--explain prints the search order" 'grep -q "^reader: companions looked for in this order: sidecar: --sidecar, else NAME.json; probe: --probe, else NAME.probe.exr, else the sidecar.s probe.file" out.txt'
echo '{"camera": {"fov": 50, "name": "shotcam"}, "frames": [1001, 1100]}' >comp/render.json
"$cgtmo" apply comp/render.exr -o r.png --op cgtmo >out.txt 2>err.txt
check "another tool's JSON with a camera: exit 0, a warning, the fallbacks" \
  '[ $? -eq 0 ] && grep -q "JSON of another kind" err.txt || { cat err.txt; false; }'
"$cgtmo" info comp/render.exr >out.txt 2>err.txt
check "info on it: exit 0" '[ $? -eq 0 ] || { cat err.txt; false; }'

# A display-referred input (an 8-bit PNG) is decoded from sRGB with a warning; --colorspace overrides.
oiiotool --pattern constant:color=0.5,0.5,0.5 8x4 3 -d uint8 -o grey.png
code() { /usr/bin/python3 -c "import OpenImageIO as o, sys; print(round(float(o.ImageBuf(sys.argv[1]).get_pixels(o.FLOAT)[0, 0, 0]) * 255))" "$1"; }
"$cgtmo" apply grey.png -o grey-out.png --op linear >out.txt 2>err.txt
check "an 8-bit PNG: one warning that it is display-referred, and code 128 comes back as 128" \
  '[ "$(grep -c "display-referred" err.txt)" -eq 1 ] && grep -q "an 8-bit PNG" err.txt && [ "$(code grey-out.png)" -eq 128 ] || { cat err.txt; code grey-out.png; false; }'
"$cgtmo" apply grey.png -o grey-lin.png --op linear --colorspace "Linear Rec.709" >out.txt 2>err.txt
check "--colorspace names it linear: no warning, 0.5 is light (code 188)" \
  '! grep -q "display-referred" err.txt && [ "$(code grey-lin.png)" -eq 188 ] || { cat err.txt; code grey-lin.png; false; }'

# bake never writes to a default folder; --into finds the shipped config from the program.
mkdir -p bakehere && (cd bakehere && "$cgtmo" bake >../out.txt 2>../err.txt; echo $? >../rc.txt)
check "bare 'cgtmo bake': exit 2, one line naming --out-luts and --out-config, nothing written" \
  '[ "$(cat rc.txt)" -eq 2 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "out-luts DIR --out-config DIR" err.txt && [ -z "$(ls -A bakehere)" ]'
check "bake --help names the shipped config found from the program" \
  '"$cgtmo" bake --help | grep -qF "default: the shipped one, $repo/ocio_config/config.ocio"'

# The demo's side-by-side: CG-TMO beside Blender's Filmic, the most different region named.
"$cgtmo" apply "$hdr" -o demo.png --op cgtmo -q 2>/dev/null
/usr/bin/python3 "$repo/scripts/demo_sheet.py" "$hdr" demo.png sheet.png >out.txt 2>err.txt
check "demo sheet: written, and the line says where to look" \
  '[ $? -eq 0 ] && [ -s sheet.png ] && grep -q "^wrote sheet.png: They differ most in the boxed region ([a-z]*-[a-z]* of the frame)" out.txt || { cat out.txt err.txt; false; }'
/usr/bin/python3 "$repo/scripts/demo_sheet.py" missing.exr demo.png sheet2.png >out.txt 2>err.txt
check "demo sheet of a missing render: exit 1, one line, nothing written" \
  '[ $? -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "cannot read .missing.exr" err.txt && [ ! -e sheet2.png ]'

# apply --help: synopsis, then examples, then the options, then the prose.
"$cgtmo" apply --help >help.txt
check "apply --help: SYNOPSIS < EXAMPLES < options < DESCRIPTION" \
  '/usr/bin/python3 -c "
t = open(\"help.txt\").read()
at = [t.index(k) for k in (\"SYNOPSIS\", \"EXAMPLES\", \"Options:\", \"DESCRIPTION\")]
assert at == sorted(at), at
"'
exit $fail
