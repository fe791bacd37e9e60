#!/usr/bin/env bash
# Hostile inputs: files the tool reads that are not what they claim to be.
#   - not a regular file (/dev/zero, a FIFO, a link to a device) as the render, the probe, the
#     sidecar, eval's input, the OCIO config or the camera table: refused at once, never a hang;
#   - an EXR whose header declares far more pixels than its bytes could hold, or than the memory
#     budget (--max-memory) allows, or a display window that with the work of the command reading
#     it exceeds the budget: refused with one line before any pixel is allocated;
#   - a deep EXR, and a probe without RGB: one line naming the file and the problem;
#   - a sidecar that is JSON but not an object: bad data (exit 1) in info, apply and sequences.
# Usage: hostile_inputs.sh CGTMO_BINARY WORK_DIR   (exit 0 pass, 1 fail)
set -u
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
py=/usr/bin/python3
failed=0

# expect CASE RC TEXT CMD...: CMD (bounded to 10 CPU seconds: bounded.sh) exits RC and its stderr, one line, holds TEXT.
expect() {
  local name=$1 rc=$2 text=$3
  shift 3
  bounded 10 "$@" >"$work/$name.out" 2>"$work/$name.err" </dev/null
  local got=$?
  local lines
  lines=$(wc -l <"$work/$name.err")
  if [ "$got" -eq "$rc" ] && grep -qF -- "$text" "$work/$name.err" && [ "$lines" -eq 1 ]; then
    echo "ok   $name"
  else
    echo "FAIL $name: exit $got (want $rc), stderr ($lines lines):"
    sed 's/^/     /' "$work/$name.err" | head -5
    [ "$got" -eq 124 ] && echo "     (timed out: the tool hung)"
    failed=1
  fi
}

# Small valid renders, and hostile EXRs made from them by patching the header's dataWindow (box2i:
# xMin, yMin, xMax, yMax as int32 little endian) or by writing a deep image.
"$py" - "$work" <<'EOF' || { echo "FAIL making inputs"; exit 1; }
import os, struct, sys
import numpy as np
import OpenImageIO as oiio
w = sys.argv[1]

def write(name, width, height, channels=("R", "G", "B"), compression="zip"):
    spec = oiio.ImageSpec(width, height, len(channels), "half")
    spec.channelnames = channels
    spec.attribute("compression", compression)
    out = oiio.ImageOutput.create(os.path.join(w, name))
    assert out.open(os.path.join(w, name), spec), out.geterror()
    out.write_image(np.full((height, width, len(channels)), 0.5, dtype=np.float16))
    out.close()

def patch_window(src, dst, x_max):
    b = bytearray(open(os.path.join(w, src), "rb").read())
    at = b.index(b"dataWindow\0box2i\0") + len(b"dataWindow\0box2i\0") + 4
    x0, y0, _, y1 = struct.unpack_from("<4i", b, at)
    struct.pack_into("<4i", b, at, x0, y0, x_max, y1)
    open(os.path.join(w, dst), "wb").write(b)

for name in ("r.exr", "side.exr", "probe.exr", "norgb.exr"):
    write(name, 64, 32)
write("norgb.probe.exr", 64, 32, channels=("Z",))
write("small.exr", 1000, 54)                      # ZIP, about 1 KB
write("budget.exr", 1000, 540)                    # 6.2 MB as float32
patch_window("small.exr", "wide.exr", 7700000)    # declares 7,700,001 x 54
patch_window("small.exr", "wider.exr", 100000000) # declares 100,000,001 x 54
write("raw.exr", 64, 32, compression="none")
# A 96x54 data window in a 3,932,256x54 display window: 2.4 GB as float32 from a file of 562 bytes.
spec = oiio.ImageSpec(96, 54, 3, "half")
spec.full_width, spec.full_height = 3932256, 54
out = oiio.ImageOutput.create(os.path.join(w, "wide_display.exr"))
assert out.open(os.path.join(w, "wide_display.exr"), spec), out.geterror()
out.write_image(np.full((54, 96, 3), 0.5, dtype=np.float16))
out.close()
# A 1x54 data window in a 1x3,000,000 display window: 34 MB to read, but fast's node grid is
# padded sideways, so each row costs about 1.25 KB however narrow the frame (found by fuzz_exr_windows).
spec = oiio.ImageSpec(1, 54, 3, "half")
spec.full_width, spec.full_height = 1, 3000000
out = oiio.ImageOutput.create(os.path.join(w, "tall_display.exr"))
assert out.open(os.path.join(w, "tall_display.exr"), spec), out.geterror()
out.write_image(np.full((54, 1, 3), 0.5, dtype=np.float16))
out.close()
patch_window("raw.exr", "raw_wide.exr", 639)      # 640 x 32 declared, 64 x 32 stored

spec = oiio.ImageSpec(4, 2, 5, "float")
spec.channelnames = ("R", "G", "B", "A", "Z")
spec.deep = True
out = oiio.ImageOutput.create(os.path.join(w, "deep.exr"))
assert out.open(os.path.join(w, "deep.exr"), spec), out.geterror()
dd = oiio.DeepData()
dd.init(spec)
for px in range(8):
    dd.set_samples(px, 1)
    for c in range(5):
        dd.set_deep_value(px, c, 0, 0.5)
out.write_deep_image(dd)
out.close()
EOF
mkfifo "$work/fifo.exr" "$work/side.json" "$work/probe.probe.exr" "$work/fifo.ocio" "$work/fifo.dorf" || exit 1
ln -s /dev/zero "$work/zero.exr"
w=$work

# 1. Not a regular file: refused, never read (before the fix: info and apply on /dev/zero spun forever
#    in OIIO's format probe; a FIFO blocked in open).
expect dev_zero_info 1 "'/dev/zero': not a regular file (character device)" "$cgtmo" info /dev/zero
expect dev_zero_apply 1 "'/dev/zero': not a regular file (character device)" "$cgtmo" apply /dev/zero -o "$w/o.png"
expect link_to_dev_zero 1 "zero.exr': not a regular file (character device)" "$cgtmo" info "$w/zero.exr"
expect fifo_render_info 1 "fifo.exr': not a regular file (FIFO)" "$cgtmo" info "$w/fifo.exr"
expect fifo_render_apply 1 "fifo.exr': not a regular file (FIFO)" "$cgtmo" apply "$w/fifo.exr" -o "$w/o.png"
expect fifo_sidecar 1 "sidecar '$w/side.json': not a regular file (FIFO)" "$cgtmo" info "$w/side.exr"
expect fifo_probe 1 "probe.probe.exr': not a regular file (FIFO)" "$cgtmo" info "$w/probe.exr"
expect fifo_explicit_sidecar 1 "not a regular file (FIFO)" "$cgtmo" info "$w/r.exr" --sidecar "$w/side.json"
expect fifo_eval_input 1 "fifo.exr': not a regular file (FIFO)" "$cgtmo" eval "$w/fifo.exr" "$w/r.exr"
expect fifo_colorconfig 2 "fifo.ocio' (--colorconfig): not a regular file (FIFO)" \
  "$cgtmo" apply "$w/r.exr" -o "$w/o.png" --colorconfig "$w/fifo.ocio"
expect fifo_camera_table 1 "fifo.dorf': not a regular file (FIFO)" \
  "$cgtmo" apply "$w/r.exr" -o "$w/o.png" --op camera -p "table=$w/fifo.dorf"

# 2. Declared size: refused from the header, before any allocation proportional to the image
#    (before the fix: 'wide' allocated 6-7 GB and info printed zeros; 'wider' said std::bad_alloc).
expect huge_window_info 1 "declares 7700001x54 pixels, 3 channels (zip, at most 1032:1)" "$cgtmo" info "$w/wide.exr"
expect huge_window_apply 1 "(corrupt or truncated)" "$cgtmo" apply "$w/wide.exr" -o "$w/o.png"
expect huger_window_info 1 "declares 100000001x54 pixels" "$cgtmo" info "$w/wider.exr"
expect uncompressed_short 1 "(none, at most 1:1)" "$cgtmo" info "$w/raw_wide.exr"
expect budget_info 1 "1000x540 pixels, 3 channels need 6.2 MB to read as float32, more than the memory budget of 4 MB" \
  "$cgtmo" info "$w/budget.exr" --max-memory 4
expect budget_apply 1 "more than the memory budget of 4 MB (--max-memory)" \
  "$cgtmo" apply "$w/budget.exr" -o "$w/o.png" --max-memory 4
if bounded 10 "$cgtmo" info "$w/budget.exr" --max-memory 7 >/dev/null 2>&1 &&
   bounded 10 "$cgtmo" apply "$w/r.exr" -o "$w/o.png" -q; then
  echo "ok   within_budget_reads"
else
  echo "FAIL within_budget_reads: a valid file within the budget was refused"
  failed=1
fi

# The display window, which no byte of the file bounds, is held to the budget with the work of
# the path that reads it (before: info 2.5 GB, apply --op drago to EXR 7.6 GB, --op cgtmo past
# 18 GB), before anything is allocated by it; the data window alone reads.
dw="'$w/wide_display.exr': the display window 3932256x54 at (0,0) (data window 96x54 at (0,0)) needs 2.4 GB to read as float32 (3 values a pixel)"
expect display_window_info 1 "$dw, more than the memory budget of 2000 MB (--max-memory)" \
  /usr/bin/time -f %M -o "$w/rss_info" "$cgtmo" info "$w/wide_display.exr" --max-memory 2000
expect display_window_drago 1 "$dw and 9.8 GB with the work of --op drago, more than the memory budget of 4000 MB" \
  /usr/bin/time -f %M -o "$w/rss_drago" "$cgtmo" apply "$w/wide_display.exr" -o "$w/o.exr" --op drago --max-memory 4000
expect display_window_cgtmo 1 "$dw and 26.3 GB with the work of --op cgtmo (filter fast), more than the memory budget of 8000 MB" \
  /usr/bin/time -f %M -o "$w/rss_cgtmo" "$cgtmo" apply "$w/wide_display.exr" -o "$w/o.png" --op cgtmo --max-memory 8000
# Before: refused only past 132 MB of work, so --op cgtmo ran and held 3.8 GB.
expect display_window_tall_cgtmo 1 "'$w/tall_display.exr': the display window 1x3000000 at (0,0) (data window 1x54 at (0,0)) needs 34.3 MB to read as float32 (3 values a pixel) and 4.0 GB with the work of --op cgtmo (filter fast), more than the memory budget of 2000 MB" \
  /usr/bin/time -f %M -o "$w/rss_tall_cgtmo" "$cgtmo" apply "$w/tall_display.exr" -o "$w/o.exr" --op cgtmo --max-memory 2000
for path in info drago cgtmo tall_cgtmo; do
  rss=$(( $(tail -1 "$w/rss_$path") / 1024 ))
  if [ "$rss" -lt 400 ]; then echo "ok   display_window_$path: refused at ${rss} MB"; else echo "FAIL display_window_$path: ${rss} MB"; failed=1; fi
done
if bounded 20 "$cgtmo" apply "$w/wide_display.exr" -o "$w/o.png" --op cgtmo --window data -q 2>/dev/null && [ -s "$w/o.png" ]; then
  echo "ok   display_window_data_window_reads"
else
  echo "FAIL display_window_data_window_reads"
  failed=1
fi

# 3. Messages that name the file.
expect deep_info 1 "deep.exr': deep images are not supported" "$cgtmo" info "$w/deep.exr"
expect deep_apply 1 "deep.exr': deep images are not supported" "$cgtmo" apply "$w/deep.exr" -o "$w/o.png"
expect probe_without_rgb 1 "norgb.probe.exr': no RGB layer found" "$cgtmo" info "$w/norgb.exr"

# 4. A sidecar that is JSON but not an object (an array, null, a number, a string) is bad data in
#    every face of the CLI: info, apply with a scene operator, each frame of a sequence (before:
#    taken for another tool's file and ignored, exit 0). An object of another tool is still a
#    warning (tests/cli/exr_layouts.sh).
for kind in array:'[1, 2]':'an array' null:null:null number:42:'a number' string:'"text"':'a string'; do
  IFS=: read -r name json words <<<"$kind"
  mkdir -p "$w/side_$name"
  cp "$w/r.exr" "$w/side_$name/r.exr"
  cp "$w/r.exr" "$w/side_$name/s.0001.exr"
  printf '%s\n' "$json" >"$w/side_$name/r.json"
  printf '%s\n' "$json" >"$w/side_$name/s.0001.json"
  expect "sidecar_${name}_info" 1 "sidecar '$w/side_$name/r.json': not a JSON object ($words)" "$cgtmo" info "$w/side_$name/r.exr"
  expect "sidecar_${name}_apply" 1 "sidecar '$w/side_$name/r.json': not a JSON object ($words)" \
    "$cgtmo" apply "$w/side_$name/r.exr" -o "$w/side_$name/o.png" --op cgtmo
  expect "sidecar_${name}_explicit" 1 "sidecar '$w/side_$name/r.json': not a JSON object ($words)" \
    "$cgtmo" apply "$w/r.exr" -o "$w/side_$name/o.png" --op cgtmo --sidecar "$w/side_$name/r.json"
  # A sequence goes on to its summary: the frame's failure is one line of its own.
  bounded 10 "$cgtmo" apply "$w/side_$name/s.####.exr" -o "$w/side_$name/o.####.png" --op cgtmo -q \
    >"$w/seq.out" 2>"$w/seq.err" </dev/null
  rc=$?
  if [ $rc -eq 1 ] && grep -qxF "cgtmo apply: frame 1 failed: sidecar '$w/side_$name/s.0001.json': not a JSON object ($words)" "$w/seq.err"; then
    echo "ok   sidecar_${name}_sequence"
  else
    echo "FAIL sidecar_${name}_sequence: exit $rc (want 1)"
    sed 's/^/     /' "$w/seq.err" | head -5
    failed=1
  fi
  if ls "$w/side_$name" | grep -q '^o\.'; then
    echo "FAIL sidecar_${name}: an output was written"
    failed=1
  fi
done

rm -f "$w/o.png"
exit $failed
