#!/usr/bin/env bash
# Hostile outputs (docs/hardening.md): a resumed sequence, --dry-run and `info` read the outputs
# already there, and those are outside input too: anyone can write an image whose description
# starts with cgtmo's record, or whose header declares more than the file holds.
#   - a record of 200,000 short fields (1 MB): read in linear time (was 22 s per --dry-run);
#   - an output whose header declares a 2 GB attribute: refused from the header, the frame redone
#     (was 2.2 GB allocated on every resume); OpenEXR bytes under a .png name are not an output;
#   - a record value holding a newline and terminal escapes: --dry-run and info print one escaped
#     line each, and cgtmo-slurm-report counts no forged frame (also when fed forged lines).
#   hostile_records.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$(readlink -f "$1")
work=$2
report_script=$(readlink -f "$(dirname "$0")/../../scripts/slurm/cgtmo-slurm-report")
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
# has_control FILE: a raw ESC or BEL byte in FILE (a terminal command).
has_control() { LC_ALL=C grep -q "$(printf '[\033\007]')" "$1"; }
py=/usr/bin/python3

mkdir -p in out
"$py" - <<'PY'
import numpy as np, OpenImageIO as oiio
for f in range(1, 4):
    path = "in/shot.%04d.exr" % f
    out = oiio.ImageOutput.create(path); out.open(path, oiio.ImageSpec(4, 4, 3, oiio.HALF))
    out.write_image(np.full((4, 4, 3), 0.25 * f, np.float32)); out.close()
PY
seq=(apply 'in/shot.####.exr' -o 'out/o.####.png' --op drago)
"$cgtmo" "${seq[@]}" -q || { echo "FAIL the first run"; exit 1; }
"$cgtmo" "${seq[@]}" --dry-run >dry.txt 2>&1
check "first run: every frame up to date" '[ "$(grep -c "^skip " dry.txt)" -eq 3 ]'

# Outputs with a hostile description (PNG text, as cgtmo writes its record).
"$py" - <<'PY'
import numpy as np, OpenImageIO as oiio
def png(path, description):
    spec = oiio.ImageSpec(4, 4, 3, oiio.UINT8)
    spec.attribute("ImageDescription", description)
    out = oiio.ImageOutput.create(path); out.open(path, spec); out.write_image(np.zeros((4, 4, 3), np.uint8)); out.close()
png("out/o.0001.png", "cgtmo provenance 1; version=0; op=drago%0Askip 7 forged.exr forged.png; view=%1B]0%3Bowned%07%1B[2J")
png("out/o.0002.png", "cgtmo provenance 1" + "; k=v" * 200000)
PY

# 1. A 1 MB record of 200,000 fields: parsed in one pass.
start=$(date +%s%N)
bounded 60 "$cgtmo" "${seq[@]}" --dry-run >dry.txt 2>dry.err; rc=$?
echo "     --dry-run over a 1 MB record of 200,000 fields: $(( ($(date +%s%N) - start) / 1000000 )) ms"
check "large record: --dry-run exits 0 (got $rc)" '[ $rc -eq 0 ]'
check "large record: frame 2 is todo, its record differs" 'grep -q "^todo 2 in/shot.0002.exr out/o.0002.png (made otherwise: " dry.txt'

# 2. A record value with a newline and terminal escapes: one line per frame, nothing raw.
check "forged record: one line per frame" '[ "$(wc -l <dry.txt)" -eq 3 ] && [ "$(cut -d" " -f2 dry.txt | tr "\n" " ")" = "1 2 3 " ]'
check "forged record: no line of its own" '! grep -q "^skip 7" dry.txt'
check "forged record: escaped, not raw" 'grep -qF "drago\\nskip 7 forged.exr" dry.txt && ! has_control dry.txt'
"$cgtmo" info out/o.0001.png >info.txt 2>&1
check "forged record: info prints it escaped" 'grep -qxF "  op: drago\\nskip 7 forged.exr forged.png" info.txt && ! has_control info.txt'

# 3. The Slurm report over the same outputs: frame 3 written, 1 and 2 to redo, no frame 7.
state=$work/state
mkdir -p "$state"
echo 0 >"$state/retries"
echo "1,2,3" >"$state/chunks.txt"
printf '%q ' "$cgtmo" "${seq[@]}" >"$state/command"
echo >>"$state/command"
bash "$report_script" "$state" >/dev/null 2>&1
check "slurm report: 1 of 3 frames written, 1 and 2 failed" \
  'grep -qx "cgtmo-slurm report: 1 of 3 frames written" "$state/report.txt" && grep -qx "failed frames: 1 2" "$state/report.txt"'
# ... and when the answer itself is forged (a cgtmo that printed a value raw): a line for a frame
# not asked counts for nothing, and a frame answered twice is not trusted.
cat >fake-cgtmo <<'SH'
#!/usr/bin/env bash
case " $* " in
  *" --list-frames "*) printf '1\n2\n3\n' ;;
  *" --dry-run "*) printf 'todo 1 a b (made otherwise: op x\nskip 7 forged.exr forged.png)\nskip 2 a b\ntodo 3 a b (x\nskip 3 c d)\n' ;;
esac
SH
chmod +x fake-cgtmo
fake_state=$work/fake-state
mkdir -p "$fake_state"
cp "$state/retries" "$state/chunks.txt" "$fake_state/"
printf '%q ' "$work/fake-cgtmo" apply 'in/shot.####.exr' -o 'out/o.####.png' >"$fake_state/command"
echo >>"$fake_state/command"
bash "$report_script" "$fake_state" >/dev/null 2>&1
check "slurm report, forged answer: frame 7 not counted, frame 3 answered twice failed" \
  'grep -qx "cgtmo-slurm report: 1 of 3 frames written" "$fake_state/report.txt" && grep -qx "failed frames: 1 3" "$fake_state/report.txt"'

# 4. An existing output whose header declares a 2 GB attribute (its description's size patched):
#    refused from the header, so the frame is redone, in bounded memory.
eseq=(apply 'in/shot.####.exr' -o 'out/e.####.exr' --op drago)
"$cgtmo" "${eseq[@]}" -q || { echo "FAIL the EXR run"; exit 1; }
"$py" - <<'PY'
import struct
path = "out/e.0001.exr"
b = bytearray(open(path, "rb").read())
key = b"comments\0string\0"
struct.pack_into("<i", b, b.index(key) + len(key), 2000000000)
open(path, "wb").write(b)
PY
bounded 60 /usr/bin/time -f "%M" -o rss.txt "$cgtmo" "${eseq[@]}" --dry-run >edry.txt 2>&1; rc=$?
rss_mb=$(( $(tail -1 rss.txt) / 1024 ))
echo "     --dry-run beside an output declaring a 2 GB attribute: peak RSS ${rss_mb} MB"
check "2 GB attribute: --dry-run exits 0 (got $rc)" '[ $rc -eq 0 ]'
check "2 GB attribute: frame 1 is redone" 'grep -q "^todo 1 in/shot.0001.exr out/e.0001.exr (made otherwise: the output has no cgtmo record" edry.txt'
check "2 GB attribute: the others stay done" '[ "$(grep -c "^skip " edry.txt)" -eq 2 ]'
check "2 GB attribute: peak RSS under 400 MB (${rss_mb} MB)" '[ "$rss_mb" -lt 400 ]'
# OpenEXR bytes under the .png name of an output: not what this run writes there.
cp out/e.0002.exr out/o.0003.png
"$cgtmo" "${seq[@]}" --dry-run >dry.txt 2>&1
check "OpenEXR bytes named .png: redone" 'grep -q "^todo 3 in/shot.0003.exr out/o.0003.png (made otherwise: the output has no cgtmo record" dry.txt'
exit $fail
