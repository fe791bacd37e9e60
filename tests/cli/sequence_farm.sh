#!/usr/bin/env bash
# Resuming a sequence as a farm does (docs/sequences.md): a frame counts as done only when its
# output records the settings and input it would be made with now; --dry-run says todo, skip or
# missing (and why); progress is a line per stage in logs and a live stage on a terminal; after
# SIGTERM the counter never claims frames that did not run.
#   sequence_farm.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
cgtmo=$(readlink -f "$1")
work=$2
repo=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
summary() { grep -E '^cgtmo apply: [0-9]+ frames in' "$1" | sed 's/.*: //'; }

mkdir -p in out big/in big/out
/usr/bin/python3 - <<'PY'
import numpy as np, OpenImageIO as oiio
def write(path, w, h, k):
    img = (np.exp2(np.linspace(-4, 6, w * h * 3)) * k).reshape(h, w, 3).astype(np.float32)
    out = oiio.ImageOutput.create(path); out.open(path, oiio.ImageSpec(w, h, 3, oiio.HALF)); out.write_image(img); out.close()
for f in range(1, 4): write("in/s.%04d.exr" % f, 32, 16, f)
write("big/in/b.0001.exr", 1024, 1024, 1)
PY
for f in $(seq 2 30); do ln -s b.0001.exr "big/in/b.$(printf %04d "$f").exr"; done
seq_apply() { "$cgtmo" apply 'in/s.####.exr' -o 'out/s.####.png' "$@"; }

# 1. Settings changed between runs: the frames are redone.
seq_apply --op agx >run1.out 2>run1.err
check "agx run: 3 done" 'summary run1.err | grep -q "3 done, 0 skipped, 0 failed"'
seq_apply --op drago --exposure 2 >run2.out 2>run2.err
check "same command, --op drago --exposure 2: 3 done, none skipped" 'summary run2.err | grep -q "3 done, 0 skipped, 0 failed"'
check "the outputs record drago and exposure 2" \
  'oiiotool --info -v out/s.0002.png | grep ImageDescription | grep -q "op=drago; exposure=2;"'
check "cgtmo info lists the record" \
  '"$cgtmo" info out/s.0002.png --header-only | grep -q -x "  op: drago" && "$cgtmo" info out/s.0002.png --header-only | grep -q "^  input: s.0002.exr, [0-9]* bytes, modified "'
seq_apply --op drago --exposure 2 >run3.out 2>run3.err
check "rerun with the same settings: all skipped" 'summary run3.err | grep -q "0 done, 3 skipped, 0 failed"'
seq_apply --op drago --exposure 2 --display sRGB --view Standard >run3b.out 2>run3b.err
check "the default display and view spelled out: still skipped" 'summary run3b.err | grep -q "0 done, 3 skipped"'
seq_apply --op drago --exposure 2 --temporal 4 >run4.out 2>run4.err
check "another --temporal sigma (drago smooths lw_max, lw_a): redone" 'summary run4.err | grep -q "3 done, 0 skipped"'
seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 >/dev/null 2>run5.err
check "a parameter given: redone" 'summary run5.err | grep -q "3 done, 0 skipped"'
cfg=$repo/ocio_config/config.ocio
if [ -f "$cfg" ]; then
  mkdir -p cfgdir && cp "$cfg" cfgdir/config.ocio && ln -s cfgdir cfglink
  seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 --colorconfig cfgdir/config.ocio >/dev/null 2>run5b.err
  check "another OCIO config: redone" 'summary run5b.err | grep -q "3 done, 0 skipped"'
  seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 --colorconfig "$PWD/cfglink/./config.ocio" >/dev/null 2>run5c.err
  check "the same config by another spelling (absolute, through a symlink): skipped" 'summary run5c.err | grep -q "0 done, 3 skipped"'
  touch -d '2002-02-02' cfgdir/config.ocio
  seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 --colorconfig cfgdir/config.ocio >/dev/null 2>run5d.err
  check "the config file edited (its time changed): redone" 'summary run5d.err | grep -q "3 done, 0 skipped"'
  seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 >/dev/null 2>run5e.err
fi
touch -d '2001-01-01' in/s.0002.exr
seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 >/dev/null 2>run6.err
check "an input re-rendered (its time changed, even to an older one): that frame redone" 'summary run6.err | grep -q "1 done, 2 skipped"'
oiiotool --pattern constant:color=0.5,0.5,0.5 32x16 3 -d uint8 -o out/s.0003.png
seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 >/dev/null 2>run7.err
check "an output written by another tool: redone" 'summary run7.err | grep -q "1 done, 2 skipped"'
seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 --force >/dev/null 2>run8.err
check "--force redoes every frame" 'summary run8.err | grep -q "3 done, 0 skipped"'

# 2. --dry-run: skip, todo with the reason, missing inputs.
seq_apply --op agx --frames 1-5 --dry-run >dry.out 2>dry.err
check "--dry-run: a changed setting is todo, with what changed" \
  'grep -q "^todo 1 in/s.0001.exr out/s.0001.png (made otherwise: op drago -> agx, exposure 2 -> 0, p.b 0.8 -> (none), and 1 more)$" dry.out'
check "--dry-run: frames without an input are missing, not todo" \
  'grep -q "^missing 4 in/s.0004.exr out/s.0004.png$" dry.out && grep -q "^missing 5 " dry.out && [ $(wc -l < dry.out) -eq 5 ]'
seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 --dry-run >dry2.out 2>&1
check "--dry-run: up to date is skip" '[ "$(cut -d" " -f1 dry2.out | sort | uniq -c | xargs)" = "3 skip" ]'
check "--dry-run changed nothing" 'seq_apply --op drago --exposure 2 --temporal 4 -p b=0.8 2>&1 >/dev/null | grep -q "0 done, 3 skipped"'

# 3. Progress: a line per stage in a log; a live stage on a terminal.
seq_apply --op agx --force >log.out 2>log.err
check "log: a line per stage of each frame" \
  '[ "$(grep -c -E "^frame [1-3]: (read \(1/3\)|tone-map \(2/3\)|write \(3/3\))$" log.out)" -eq 9 ]'
check "log: a line per frame" '[ "$(grep -c -E "^\[[1-3]/3\] frame [1-3] done" log.out)" -eq 3 ]'
"$cgtmo" apply in/s.0001.exr -o single.png --op agx >single.out 2>single.err
check "one file, log: its stages, then the result" \
  'grep -q "^cgtmo apply: read (1/3) at " single.out && grep -q "^cgtmo apply: write (3/3) at " single.out && tail -1 single.out | grep -q "^wrote single.png"'
"$cgtmo" apply in/s.0001.exr -o single.png --op agx -q >quiet.out 2>&1
check "one file, -q: silent" '[ ! -s quiet.out ]'
if command -v script >/dev/null; then
  script -qfec "'$cgtmo' apply 'in/s.####.exr' -o 'out/s.####.png' --op reinhard" /dev/null >tty.out 2>&1
  check "terminal: the bar shows the stage of a frame" 'grep -a -q -E "\| frame [1-3]: (read|tone-map|write) \([1-3]/3\)" tty.out'
  check "terminal: no per-stage lines" '! grep -a -q -E "^frame [1-3]: read" tty.out'
  script -qfec "'$cgtmo' apply in/s.0001.exr -o tty1.png --op reinhard" /dev/null >tty1.out 2>&1
  check "terminal, one file: a live stage line, cleared" 'grep -a -q "cgtmo apply: read (1/3)" tty1.out && grep -a -q "wrote tty1.png" tty1.out'
else
  echo "skip terminal progress (no script(1))"
fi

# 4. SIGTERM: the frames in flight finish; the counter counts frames that ran, never all of them.
"$cgtmo" apply 'big/in/b.####.exr' -o 'big/out/b.####.png' --op agx --threads 1 >term.out 2>term.err & pid=$!
for _ in $(seq 600); do grep -q "^\[1/30\]" term.out 2>/dev/null && break; sleep 0.05; done
kill -TERM "$pid"; wait "$pid"; rc=$?
written=$(ls big/out | wc -l)
last=$(grep -E "^\[[0-9]+/30\]" term.out | tail -1 | sed -E 's/^\[([0-9]+)\/30\].*/\1/')
check "SIGTERM: exit 130, stopped early ($written of 30 written)" '[ $rc -eq 130 ] && [ "$written" -lt 30 ]'
check "SIGTERM: the last counter line ([$last/30]) counts the frames written ($written)" '[ "${last:-0}" -eq "$written" ]'
check "SIGTERM: the summary names the frames not started" 'grep -q "not started (interrupted)" term.err'

[ $fail -eq 0 ] && echo "all sequence farm checks passed"
exit $fail
