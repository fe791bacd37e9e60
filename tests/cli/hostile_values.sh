#!/usr/bin/env bash
# Values as scripts and farms pass them (docs/hardening.md):
#   - an empty value (`--bit-depth ""`, `-p mode=`) is refused like any invalid one (exit 2, one
#     line naming the option), never read as "not given", i.e. the default;
#   - both scene operators take the same output modes (-p output=scene-linear, stops=, shadows=);
#   - a display-encoded EXR holds values in [0, 1]: dwaa and dwab, which decode past it, are
#     refused there; every other compression decodes within it (measured on hard edges).
#   hostile_values.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$(readlink -f "$1")
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
py=/usr/bin/python3
# run NAME EXPECTED_RC PATTERN ARGS...: ends within 20 CPU seconds with EXPECTED_RC; with a
# PATTERN, stderr is one line matching it and no out.* was written.
run() {
  local name=$1 want=$2 pattern=$3; shift 3
  rm -f out.*
  bounded 20 "$cgtmo" "$@" >stdout.txt 2>stderr.txt; local rc=$?
  check "$name: exit $want (got $rc)" "[ $rc -eq $want ]"
  if [ -n "$pattern" ]; then
    check "$name: one-line error matching '$pattern'" '[ "$(wc -l <stderr.txt)" -eq 1 ] && grep -q -- "$pattern" stderr.txt'
    check "$name: no output" '[ -z "$(ls out.* 2>/dev/null)" ]'
  fi
  [ $rc -eq $want ] || sed 's/^/     | /' stderr.txt
}
# max_of FILE: the largest value an image decodes to (OpenImageIO, as a reader sees it).
max_of() { "$py" -c 'import sys, OpenImageIO as oiio; print("%.6f" % oiio.ImageInput.open(sys.argv[1]).read_image("float").max())' "$1"; }
# differ A B: the two images' pixels differ (their records always do).
differ() {
  "$py" -c 'import sys, numpy as np, OpenImageIO as oiio
a, b = (oiio.ImageInput.open(f).read_image("float") for f in sys.argv[1:])
sys.exit(not np.any(a != b))' "$1" "$2"
}

# A render with a log ramp and hard edges (a 4-pixel checker of 1e-4 and 1000): what rings.
"$py" - <<'PY'
import numpy as np, OpenImageIO as oiio
w = h = 64
img = np.zeros((h, w, 3), np.float32)
img[:32] = np.exp2(np.linspace(-8, 10, w))[None, :, None]
y, x = np.mgrid[0:32, 0:w]
img[32:] = (((y // 4 + x // 4) % 2) * 1000 + 1e-4)[..., None] * np.array([1, 0.6, 0.2], np.float32)
out = oiio.ImageOutput.create("in.exr"); out.open("in.exr", oiio.ImageSpec(w, h, 3, oiio.HALF)); out.write_image(img); out.close()
PY
mkdir -p seq && for f in 1 2; do cp in.exr "seq/s.000$f.exr"; done

# 1. Empty values: `--bit-depth ""` and `--compression ""` exited 0 with the default.
for opt in --bit-depth --compression --op --layer --colorspace --colorconfig --display --view --window --exr-view --pass; do
  run "apply $opt \"\"" 2 "error: $opt is given an empty value" apply in.exr -o out.exr "$opt" ""
done
run "apply --param \"\"" 2 "error: --param is given an empty value" apply in.exr -o out.exr -p ""
run "apply --output \"\"" 2 "error: --output is given an empty value" apply in.exr -o ""
run "apply --probe \"\" (cgtmo)" 2 "error: --probe is given an empty value" apply in.exr -o out.exr --op cgtmo --probe ""
run "apply --sidecar \"\" (wls)" 2 "error: --sidecar is given an empty value" apply in.exr -o out.exr --op wls --sidecar ""
run "apply --frames \"\" (every frame on disk)" 2 "error: --frames is given an empty value" \
  apply 'seq/s.####.exr' -o 'seq/o.####.png' --frames ""
check "apply --frames \"\": no frame written" '[ -z "$(ls seq | grep -v "^s\.")" ]'
for opt in --exposure --threads --max-memory --temporal; do
  run "apply $opt \"\" (a number)" 2 "$opt" apply in.exr -o out.exr "$opt" ""
done
# The library's rule for parameters, for every face: "" is refused, except for a text whose default
# is "" (camera's curve), where it is that value and resolved parameters resolve again.
run "apply -p mode= (camera)" 2 "camera: parameter 'mode' is given an empty value" apply in.exr -o out.png --op camera -p mode=
run "apply -p mode= (reinhard)" 2 "reinhard: parameter 'mode' is given an empty value" apply in.exr -o out.png --op reinhard -p mode=
run "info --layer \"\"" 2 "error: --layer is given an empty value" info in.exr --layer ""
run "eval --write \"\"" 2 "error: --write is given an empty value" eval --scenes . --write ""
run "bake --out-luts \"\"" 2 "error: --out-luts is given an empty value" bake --out-luts "" -q
# bake's --prefix "" is a value of its own (no prefix), not the default "cgtmo ": not refused as empty.
run "bake --prefix \"\" is a value" 2 "no studio config at 'missing.ocio'" bake --into missing.ocio -o merged --prefix "" -q
run "apply --bit-depth 16 (a value)" 0 "" apply in.exr -o out.png --bit-depth 16 -q

# 2. The scene operators' output modes: --op wls refused stops= and shadows= (exit 2).
"$cgtmo" list --json >list.json
check "cgtmo and wls list the same output, stops and shadows" "\"$py\" -c '
import json
ops = {o[\"name\"]: {p[\"name\"]: p for p in o[\"params\"]} for o in json.load(open(\"list.json\"))}
keys = (\"output\", \"stops\", \"shadows\")
assert all(k in ops[\"wls\"] for k in keys), sorted(ops[\"wls\"])
assert all(ops[\"wls\"][k] == ops[\"cgtmo\"][k] for k in keys)
'"
for op in cgtmo wls; do
  for v in "4 2" "8 2" "4 0"; do
    set -- $v
    run "$op output=scene-linear stops=$1 shadows=$2" 0 "" apply in.exr -o "$op-sl-$1-$2.exr" --op "$op" --no-display \
      -p output=scene-linear -p stops="$1" -p shadows="$2" -q
  done
  run "$op output=display" 0 "" apply in.exr -o "$op-d.exr" --op "$op" --no-display -q
  m=$(max_of "$op-sl-4-2.exr") md=$(max_of "$op-d.exr")
  check "$op: scene-linear is unclamped (max $m), display stays in [0, 1] (max $md)" \
    "\"$py\" -c 'import sys; a, d = map(float, sys.argv[1:]); sys.exit(not (a > 1 and d <= 1))' $m $md"
  check "$op: stops= and shadows= change the output" 'differ "$op-sl-4-2.exr" "$op-sl-8-2.exr" && differ "$op-sl-4-2.exr" "$op-sl-4-0.exr"'
done
run "wls stops= out of range" 2 "wls: parameter 'stops' = 99 is out of range" apply in.exr -o out.exr --op wls -p stops=99

# 3. Display-encoded EXR outputs stay in [0, 1]: dwaa and dwab decoded up to 1.007 on these edges.
for c in dwaa dwab; do
  for op in drago cgtmo; do
    run "$op sRGB --compression $c" 2 "compression $c is lossy and decodes display-encoded values outside \[0, 1\]" \
      apply in.exr -o out.exr --op "$op" --compression "$c" --bit-depth half
  done
  run "--no-display --compression $c (linear)" 0 "" apply in.exr -o "nd-$c.exr" --op drago --no-display --compression "$c" -q
done
run "sequence sRGB --compression dwaa" 2 "compression dwaa is lossy" apply 'seq/s.####.exr' -o 'seq/o.####.exr' --compression dwaa
check "sequence sRGB --compression dwaa: no frame written" '[ -z "$(ls seq | grep -v "^s\.")" ]'
# Every other compression, read back in one go (one interpreter: the test stays quick).
outs=()
for c in none rle zips zip piz pxr24 b44 b44a; do
  for op in drago cgtmo; do
    "$cgtmo" apply in.exr -o "$op-$c.exr" --op "$op" --compression "$c" --bit-depth half -q 2>/dev/null && outs+=("$op-$c.exr")
  done
done
check "drago and cgtmo sRGB with the 8 other compressions: all 16 written" '[ ${#outs[@]} -eq 16 ]'
"$py" -c 'import sys, OpenImageIO as oiio
for f in sys.argv[1:]: print(f, "%.6f" % oiio.ImageInput.open(f).read_image("float").max())' "${outs[@]}" >maxima.txt
while read -r f m; do
  check "$f: sRGB decodes within [0, 1] (max $m)" '[ "$m" = 1.000000 ] || [[ $m == 0.* ]]'
done <maxima.txt
exit $fail
