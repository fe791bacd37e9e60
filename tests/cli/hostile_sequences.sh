#!/usr/bin/env bash
# Hostile frame sequences (docs/hardening.md): requested frames without inputs, frames far apart,
# outputs that name another frame's input (or a scene operator's probe or sidecar), and names whose
# frame number is beyond any integer. Each case: the exit status, a one-line error or warning naming
# the file, no crash (exit < 128), bounded time, and no input modified.
#   hostile_sequences.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$(readlink -f "$1")
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
inputs_md5() { find in -type f -print0 | sort -z | xargs -0 md5sum; }
# run NAME EXPECTED_RC PATTERN ARGS...: ends within 20 CPU seconds (bounded.sh) with EXPECTED_RC
# (< 124: no crash, no limit reached), and
# stderr's lines matching 'error|warning|failed:' are one line matching PATTERN; no input changes.
run() {
  local name=$1 want=$2 pattern=$3; shift 3
  inputs_md5 >before.md5
  bounded "${cpu_limit:-20}" "$cgtmo" "$@" >stdout.txt 2>stderr.txt; local rc=$?
  check "$name: exit $want (got $rc)" "[ $rc -eq $want ]"
  check "$name: no crash, no limit reached" "[ $rc -lt 124 ]"
  if [ -n "$pattern" ]; then
    check "$name: one line matching '$pattern'" \
      '[ "$(grep -c -E "error|warning|failed:" stderr.txt)" -eq 1 ] && grep -q -- "$pattern" stderr.txt'
  fi
  check "$name: no input modified" 'inputs_md5 | cmp -s - before.md5'
  [ $rc -eq $want ] || sed 's/^/     | /' stderr.txt
}

mkdir -p in out
/usr/bin/python3 - <<'PY'
import numpy as np, OpenImageIO as oiio
def write(path, w, h, k):
    img = (np.exp2(np.linspace(-4, 4, w * h * 3)) * k).reshape(h, w, 3).astype(np.float32)
    out = oiio.ImageOutput.create(path); out.open(path, oiio.ImageSpec(w, h, 3, oiio.HALF)); out.write_image(img); out.close()
for f in range(1, 6): write("in/shot.%04d.exr" % f, 4, 4, f)
for f in (-1, 0, 1): write("in/a.%s.exr" % ("-%04d" % -f if f < 0 else "%04d" % f), 4, 4, 1)
for f in (-99999999, 99999999): write("in/far.%d.exr" % f, 4, 4, 1)
write("in/sc.0001.exr", 4, 4, 1); write("in/sc.0001.probe.exr", 8, 4, 1)
PY
cat >in/sc.0001.json <<'JSON'
{"camera":{"world_matrix":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],"fov_x_rad":0.8,"resolution":[4,4]},"lights":[]}
JSON

# 1. Requested frames with no input, with a temporally smoothed operator (was SIGSEGV).
run "no input for any frame asked" 1 "frames 1-3 of 'in/missing.####.exr' not found (on disk: none)" \
  apply 'in/missing.####.exr' -o 'out/m.####.png' --frames 1-3 --op drago
run "frames asked beyond the shot" 1 "frames 100-102 of 'in/shot.####.exr' not found (on disk: 1-5)" \
  apply 'in/shot.####.exr' -o 'out/b.####.png' --frames 100-102 --op drago
# --list-frames (what cgtmo-slurm asks before it queues) refuses the same, in the same words.
run "frames asked beyond the shot, --list-frames" 1 "frames 100-240 of 'in/shot.####.exr' not found (on disk: 1-5)" \
  apply 'in/shot.####.exr' -o 'out/b.####.png' --frames 100-240 --op drago --list-frames
check "frames asked beyond the shot, --list-frames: no frame listed" '[ ! -s stdout.txt ]'
run "some frames asked have no input" 1 "frame 6 failed: .*in/shot.0006.exr" \
  apply 'in/shot.####.exr' -o 'out/c.####.png' --frames 4-6 --op drago -q
check "some frames asked have no input: the others are done" '[ -s out/c.0004.png ] && [ -s out/c.0005.png ] && [ ! -e out/c.0006.png ]'

# 2. Two frames 200 million apart: smoothing walked (and allocated) the whole gap (60 s, 3.2 GB).
cpu_limit=10 run "frames -99999999 and 99999999 (10 CPU seconds)" 0 "" apply 'in/far.#.exr' -o 'out/far.#.png' --op drago -q
check "frames -99999999 and 99999999: both written" '[ -s out/far.-99999999.png ] && [ -s out/far.99999999.png ]'

# 3. An output that is an input of another frame, or a scene operator's probe or sidecar.
run "frame 1 writes frame -1's input" 2 "output 'in/a.-0001.exr' (frame 1) is an input of frame -1" \
  apply 'in/a.####.exr' -o 'in/a.-####.exr' --frames=-1-1 --op drago
ln -s in alias
run "same, through a symlinked folder" 2 "output 'alias/a.-0001.exr' is the input 'in/a.-0001.exr'" \
  apply 'in/a.####.exr' -o 'alias/a.-####.exr' --frames=-1-1 --op drago
run "sequence output on the probe" 2 "'in/sc.0001.probe.exr' (frame 1) is an input of frame 1" \
  apply 'in/sc.####.exr' -o 'in/sc.####.probe.exr' --op cgtmo --no-display --force
run "output on the probe" 2 "output 'in/./sc.0001.probe.exr' is the input 'in/sc.0001.probe.exr'" \
  apply in/sc.0001.exr -o in/./sc.0001.probe.exr --op cgtmo --no-display
ln -s sc.0001.json in/sidecar_alias.exr
run "output through a symlink to the sidecar" 2 "is the input 'in/sc.0001.json'" \
  apply in/sc.0001.exr -o in/sidecar_alias.exr --op wls --no-display
ln in/sc.0001.probe.exr out/probe_hardlink.exr
run "output on a hard link of the probe" 2 "output 'out/probe_hardlink.exr' is the input 'in/sc.0001.probe.exr'" \
  apply in/sc.0001.exr -o out/probe_hardlink.exr --op cgtmo --no-display
check "refused runs wrote nothing" '[ -z "$(ls out | grep -v -E "^(c|far)\.|^probe_hardlink")" ]'

# 4. A name whose frame number is beyond long: 'error: stol' aborted the whole shot.
cp in/shot.0001.exr in/shot.99999999999999999999.exr
run "frame number beyond long" 0 "warning: ignoring 'shot.99999999999999999999.exr': frame number out of range" \
  apply 'in/shot.####.exr' -o 'out/d.####.png' --op drago -q
check "frame number beyond long: the shot is done" '[ "$(ls out | grep -c "^d\.")" -eq 5 ]'

exit $fail
