#!/usr/bin/env bash
# Output names at the filesystem's limit: the temporary written beside the output (and renamed
# over it) must fit whenever the output's own name fits (NAME_MAX, 255 bytes), for one file and
# for a sequence's frames, and nothing but the outputs may be left.
#   hostile_temp_names.sh CGTMO_BINARY WORK_DIR
set -uo pipefail
cgtmo=$(readlink -f "$1")
work=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
in="$root/tests/scenes/cornell/cornell.exr"
rm -rf "$work" && mkdir -p "$work" && work=$(cd "$work" && pwd)
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
a() { printf 'a%.0s' $(seq "$1"); }

for n in 240 251; do  # 244 and 255 bytes with ".png"
  out="$work/$n"; mkdir -p "$out"
  name="$(a "$n").png"
  err=$("$cgtmo" apply "$in" -o "$out/$name" --op linear -q 2>&1); rc=$?
  check "apply to a ${#name}-byte name: exit 0 (${err:-no error})" '[ $rc -eq 0 ]'
  check "apply to a ${#name}-byte name: the output and nothing else" '[ "$(ls -A "$out")" = "$name" ]'
done

# A sequence whose frame names are 255 bytes: 246 + "." + 4 digits + ".png".
seq="$work/seq"; mkdir -p "$seq/in" "$seq/out"
ln -s "$in" "$seq/in/s.0001.exr"
stem=$(a 246)
err=$("$cgtmo" apply "$seq/in/s.####.exr" -o "$seq/out/$stem.####.png" --op linear -q 2>&1); rc=$?
check "sequence to 255-byte frame names: exit 0 (${err:-no error})" '[ $rc -eq 0 ]'
check "sequence to 255-byte frame names: the frame and nothing else" '[ "$(ls -A "$seq/out")" = "$stem.0001.png" ]'

exit $fail
