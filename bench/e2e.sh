#!/usr/bin/env bash
# End to end: `cgtmo apply IN -o OUT.png` against oiiotool reading the same multilayer EXR and
# writing the same 8-bit RGBA PNG with a plain linear -> sRGB conversion, side by side with
# hyperfine; then the stages of cgtmo apply (bench_e2e_stages). docs/performance.md has the figures.
#
# Usage: bench/e2e.sh [BUILD_DIR] [RUNS]
#   BUILD_DIR  a Release build with CGTMO_BUILD_BENCH=ON (default: build-bench)
#   RUNS       hyperfine runs per command (default: 15)
# Input: the committed Blender frame tests/scenes/bench/*.exr when present, else a synthetic
# Blender-style multilayer EXR made by bench/make_multilayer_exr.py in BUILD_DIR/e2e.
# Outputs (all in BUILD_DIR/e2e): the PNGs, e2e.json and e2e.md (hyperfine), e2e-summary.md.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build-bench}" && pwd)
runs=${2:-15}
cgtmo=$build/apps/cgtmo/cgtmo
stages=$build/bench/bench_e2e_stages
work=$build/e2e
mkdir -p "$work"
for tool in "$cgtmo" "$stages"; do
  [ -x "$tool" ] || { echo "e2e.sh: $tool missing: build with -DCGTMO_BUILD_BENCH=ON first" >&2; exit 2; }
done
command -v hyperfine >/dev/null || { echo "e2e.sh: hyperfine missing (scripts/install-deps.sh)" >&2; exit 2; }

in=$(ls "$root"/tests/scenes/bench/*.exr 2>/dev/null | head -1 || true)
if [ -z "$in" ]; then
  in=$work/multilayer.exr
  [ -f "$in" ] || /usr/bin/python3 "$root/bench/make_multilayer_exr.py" "$in"
fi

# The beauty prefix cgtmo picks (the first <layer>.Combined), for oiiotool's --ch.
prefix=$(oiiotool --info -v "$in" | tr ',' '\n' | grep -o '[A-Za-z0-9_ ]*\.Combined\.R' | head -1 | sed -e 's/^ *//' -e 's/\.R$//')
[ -n "$prefix" ] || { echo "e2e.sh: no <layer>.Combined.R channel in $in" >&2; exit 1; }
ch="R=$prefix.R,G=$prefix.G,B=$prefix.B"
oiiotool --info -v "$in" | grep -q "$prefix.A" && ch="$ch,A=$prefix.A"

# Both sides single-process, all cores (cgtmo's and oiiotool's defaults), no OCIO variable: cgtmo
# uses its built-in config (sRGB display, Standard view = the sRGB encoding), oiiotool its built-in
# linear -> sRGB conversion.
unset OCIO
echo "input: $in ($(du -h "$in" | cut -f1), beauty $prefix)"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; load: $(cut -d' ' -f1-3 /proc/loadavg)"
hyperfine --warmup 2 --runs "$runs" --export-json "$work/e2e.json" --export-markdown "$work/e2e.md" \
  -n "oiiotool --ch + --colorconvert linear sRGB" \
  "oiiotool '$in' --ch $ch --colorconvert linear sRGB -o '$work/oiiotool.png'" \
  -n "cgtmo apply --op linear" "'$cgtmo' apply '$in' -o '$work/cgtmo-linear.png' --op linear -q" \
  -n "cgtmo apply --op reinhard" "'$cgtmo' apply '$in' -o '$work/cgtmo-reinhard.png' --op reinhard -q" \
  -n "cgtmo apply --op agx" "'$cgtmo' apply '$in' -o '$work/cgtmo-agx.png' --op agx -q" \
  -n "cgtmo apply --op drago" "'$cgtmo' apply '$in' -o '$work/cgtmo-drago.png' --op drago -q"

# Same work, same output: the linear operator (clip, then sRGB) against oiiotool's conversion
# (which the 8-bit PNG write clips), pixel for pixel.
echo
echo "cgtmo --op linear vs oiiotool, 8-bit PNGs:"
oiiotool "$work/cgtmo-linear.png" --printinfo:verbose=0 2>/dev/null | head -1 || true
oiiotool "$work/oiiotool.png" --printinfo:verbose=0 2>/dev/null | head -1 || true
idiff -fail 0.004 -warn 0.004 "$work/cgtmo-linear.png" "$work/oiiotool.png" | tail -4 || true

/usr/bin/python3 - "$work/e2e.json" "$work/e2e-summary.md" <<'EOF'
import json, sys
res = json.load(open(sys.argv[1]))["results"]
base = res[0]["median"]
lines = ["| command | median (s) | min (s) | max (s) | ratio to oiiotool (medians) |", "|---|---:|---:|---:|---:|"]
for r in res:
    lines.append(f"| {r['command']} | {r['median']:.3f} | {r['min']:.3f} | {r['max']:.3f} | {r['median'] / base:.2f} |")
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
print()
print("\n".join(lines))
EOF

echo
echo "stages of cgtmo apply (bench_e2e_stages, real time, all threads):"
"$stages" --input="$in" --output-dir="$work" --benchmark_min_time=0.5 --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true 2>&1 | grep -E "input|_median|^---|Benchmark" || true
