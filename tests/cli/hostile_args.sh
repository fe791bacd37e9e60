#!/usr/bin/env bash
# Hostile command lines (docs/hardening.md): values that pass naive range checks (NaN, infinities,
# numbers beyond int in a sidecar, thread counts), advertised range ends, and file names that are
# not UTF-8 with --json. Each case: the exit status, a one-line error naming the problem, bounded CPU
# time, and no output written on error.
#   hostile_args.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$(readlink -f "$1")
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
# run NAME EXPECTED_RC PATTERN ARGS...: the run ends within 20 CPU seconds (bounded.sh) with EXPECTED_RC, its stderr is one
# line matching PATTERN (empty pattern: no error expected), and out.png exists only on success.
run() {
  local name=$1 want=$2 pattern=$3; shift 3
  rm -f out.png
  bounded "${cpu_limit:-20}" "$cgtmo" "$@" >stdout.txt 2>stderr.txt; local rc=$?
  check "$name: exit $want (got $rc)" "[ $rc -eq $want ]"
  if [ -n "$pattern" ]; then
    check "$name: one-line error matching '$pattern'" \
      '[ "$(wc -l <stderr.txt)" -eq 1 ] && grep -q -- "$pattern" stderr.txt'
    check "$name: no output" '[ ! -e out.png ]'
  fi
}

/usr/bin/python3 - <<'PY'
import numpy as np, OpenImageIO as oiio
img = np.exp2(np.linspace(-6, 6, 8 * 8 * 3)).reshape(8, 8, 3).astype(np.float32)
out = oiio.ImageOutput.create("in.exr"); out.open("in.exr", oiio.ImageSpec(8, 8, 3, oiio.HALF)); out.write_image(img); out.close()
PY
mkdir -p seq && for f in 1 2 3; do cp in.exr "seq/s.000$f.exr"; done

# NaN passes 'v < lo || v > hi'; every numeric option must refuse it (and infinities) at parse time.
run "temporal nan" 2 "--temporal: 'nan' is not a finite number" apply 'seq/s.####.exr' -o 'seq/o.####.png' --temporal nan
run "temporal inf" 2 "--temporal: 'inf' is not a finite number" apply 'seq/s.####.exr' -o 'seq/o.####.png' --temporal inf
run "temporal negative" 2 "--temporal: '-1' is not in \[0, 1000\]" apply 'seq/s.####.exr' -o 'seq/o.####.png' --temporal -1
run "max-memory nan" 2 "--max-memory: 'nan' is not a finite number" apply 'seq/s.####.exr' -o 'seq/o.####.png' --max-memory nan
run "max-memory zero" 2 "--max-memory: '0' is not in" apply 'seq/s.####.exr' -o 'seq/o.####.png' --max-memory 0
check "no sequence output after the refused runs" '[ -z "$(ls seq | grep -v "^s\.")" ]'
run "exposure nan" 2 "--exposure: 'nan' is not a finite number" apply in.exr -o out.png --exposure nan
run "exposure -inf" 2 "--exposure: '-inf' is not a finite number" apply in.exr -o out.png --exposure=-inf
run "exposure 1e400" 2 "--exposure: '1e400' is not a finite number" apply in.exr -o out.png --exposure 1e400
run "exposure 65" 2 "--exposure: '65' is not in \[-64, 64\]" apply in.exr -o out.png --exposure 65
# --display/--view without display encoding: one message from the library, for either pipeline.
run "no-display with display" 2 "error: --no-display: a display or view cannot be combined with linear (unencoded) output$" \
  apply in.exr -o out.png --no-display --display sRGB
run "no-display with view (cgtmo)" 2 "error: --no-display: a display or view cannot be combined with linear (unencoded) output$" \
  apply in.exr -o out.png --op cgtmo --no-display --view Standard
run "param nan" 2 "needs a number, got 'nan'" apply in.exr -o out.png --op reinhard-ext -p white=nan
# bake --max-error nan ran the whole bake (91 s) before failing; it must stop at parse time.
# A bake takes minutes of CPU; the refusal must come within 5 CPU seconds (the kernel stops it past them).
cpu_limit=5 run "bake max-error nan" 2 "--max-error: 'nan' is not a finite number" bake --max-error nan --out-luts . --out-config . -q
check "bake max-error nan: nothing written" '[ ! -e config.ocio ] && [ -z "$(ls -A | grep -i -E "\.(cube|clf|ctf|spi1d|spi3d)$|staging")" ]'

# The minimum 'cgtmo list' advertises for a parameter works with the other defaults.
min_p=$("$cgtmo" list --json | /usr/bin/python3 -c '
import json, sys
op = next(o for o in json.load(sys.stdin) if o["name"] == "uchimura")
print(next(p["min"] for p in op["params"] if p["name"] == "max_brightness"))')
check "list advertises a minimum for uchimura's max_brightness ($min_p)" '[ -n "$min_p" ]'
run "uchimura max_brightness=$min_p (the advertised minimum)" 0 "" apply in.exr -o out.png --op uchimura -p "max_brightness=$min_p" -q
check "uchimura at its advertised minimum: output written" '[ -s out.png ]'

# An empty word that is no option's value: CLI11 took it for an option group's (empty) name and
# looped forever (found by fuzz_cli_args). One line, exit 2, at once, wherever it stands.
run "empty word after IN" 2 "argument 2 is empty" apply in.exr "" -o out.png
run "empty word at the end" 2 "argument 4 is empty" apply in.exr -o out.png ""
run "empty word after a flag" 2 "argument 5 is empty" apply in.exr -o out.png --no-display ""
run "empty word in a sequence" 2 "argument 2 is empty" apply 'seq/s.####.exr' "" -o 'seq/o.####.png' --dry-run
run "empty word to info" 2 "argument 2 is empty" info in.exr ""
run "empty value of an option is its value" 2 "--param is given an empty value" apply in.exr -o out.png -p ""

# Sidecar numbers beyond int: converted before the range check (undefined behaviour) until fixed.
for res in 1e10 2147483648 1e300; do
  printf '{"camera": {"world_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "fov_x_rad": 1.0, "resolution": [%s, 8]}, "lights": []}' "$res" >big.json
  run "sidecar resolution $res" 1 "big.json.*camera.resolution is not \[width, height\]" info in.exr --sidecar big.json
done

# Thread counts: the library's one range, 0 to 1024, for every face (the Python module's
# set_threads crashed at 40,000 and took -1).
run "threads 1025" 2 "--threads: Value 1025 not in range 0 to 1024" apply in.exr -o out.png --threads 1025
run "threads -1" 2 "--threads: Value -1 not in range 0 to 1024" apply in.exr -o out.png --threads -1
run "threads 1024" 0 "" apply in.exr -o out.png --threads 1024 -q
check "threads 1024: output written" '[ -s out.png ]'

# --json with file names that are not UTF-8 (any bytes are a name on Linux): it wrote the output,
# then exited 1 with the JSON library's exception and printed no JSON. Each byte outside UTF-8 is
# written \udcXX, so os.fsencode(json.loads(...)[...]) gives the name back (docs/outputs.md).
in_name=$(printf 'in-\377.exr') out_name=$(printf 'out-\376\303.png')
cp in.exr "$in_name"
mkdir -p nonutf8 && for f in 1 2; do cp in.exr "nonutf8/$(printf 's\377').000$f.exr"; done
json_names_ok() {  # json_names_ok FILE IN OUT: one JSON object whose input and output are IN and OUT, byte for byte
  /usr/bin/python3 -c '
import json, os, sys
text = open(sys.argv[1], "rb").read()
j = json.loads(text)
assert text.count(b"\n") == 1, text
assert os.fsencode(j["input"]) == os.fsencode(sys.argv[2]) and os.fsencode(j["output"]) == os.fsencode(sys.argv[3]), j
' "$@" 2>&1
}
for op in drago cgtmo; do
  rm -f "$out_name"
  bounded 20 "$cgtmo" apply "$in_name" -o "$out_name" --op $op --json >stdout.txt 2>stderr.txt; rc=$?
  check "--json $op, names not UTF-8: exit 0 (got $rc)" '[ $rc -eq 0 ]'
  check "--json $op, names not UTF-8: the names round-trip" 'json_names_ok stdout.txt "$in_name" "$out_name"'
  check "--json $op, names not UTF-8: output written" '[ -s "$out_name" ]'
done
bounded 20 "$cgtmo" apply "nonutf8/$(printf 's\377').####.exr" -o "nonutf8/$(printf 'o\376').####.png" --json >stdout.txt 2>stderr.txt; rc=$?
check "--json sequence, names not UTF-8: exit 0 (got $rc)" '[ $rc -eq 0 ]'
check "--json sequence, names not UTF-8: the names round-trip" \
  'json_names_ok stdout.txt "nonutf8/$(printf "s\377").####.exr" "nonutf8/$(printf "o\376").####.png"'

exit $fail
