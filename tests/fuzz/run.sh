#!/usr/bin/env bash
# Runs the libFuzzer targets of a CGTMO_FUZZ build: each for SECONDS, starting from the committed
# seed corpus (copied, so the repository is not modified), and fails on any crash or finding.
#   tests/fuzz/run.sh BUILD_DIR SECONDS [fuzz_name...]
# Findings (crash-*, leak-*, timeout-* files) are kept in BUILD_DIR/fuzz-work/<name>/. A dictionary
# tests/fuzz/<name>.dict (option names, keywords) is passed to its target when present.
set -euo pipefail
build=$(cd "$1" && pwd) seconds=$2  # absolute: fuzz_cli_args runs inside a folder of its own
shift 2
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$build"/tests/fuzz/fuzz_*; do [ -x "$f" ] && targets+=("$(basename "$f")"); done
fi
[ ${#targets[@]} -gt 0 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }
failed=0
for t in "${targets[@]}"; do
  name=${t#fuzz_}
  work="$build/fuzz-work/$name"
  mkdir -p "$work/corpus" "$work/findings"
  seed="$here/corpus/$name"
  [ -d "$seed" ] && cp -n "$seed"/* "$work/corpus/" 2>/dev/null || true
  log="$work/run.log"
  dict=()
  [ -f "$here/$name.dict" ] && dict=(-dict="$here/$name.dict")
  # fuzz_exr_header proves an allocation bound: its reader has a 16 MB budget, and no single
  # allocation may exceed that plus OpenImageIO's 64 MB scanline conversion buffer, plus 16 MB
  # (an out-of-memory finding otherwise).
  limits=(-rss_limit_mb=3072)
  [ "$name" = exr_header ] && limits+=(-malloc_limit_mb=96)
  if "$build/tests/fuzz/$t" "${dict[@]}" -max_total_time="$seconds" -timeout=20 "${limits[@]}" -print_final_stats=1 \
       -artifact_prefix="$work/findings/" "$work/corpus" >"$log" 2>&1; then
    runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
    cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
    echo "fuzz $name: ok, ${runs:-?} executions in ${seconds}s, coverage ${cov:-?} edges, corpus $(ls "$work/corpus" | wc -l) inputs"
  else
    echo "fuzz $name: FAILED (finding in $work/findings/); log tail:"
    tail -30 "$log"
    failed=1
  fi
done
exit $failed
