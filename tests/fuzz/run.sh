#!/usr/bin/env bash
# Runs the libFuzzer targets of a CGTMO_FUZZ build (docs/hardening.md, "Fuzzing"), every target of
# BUILD_DIR/tests/fuzz unless names are given.
#
#   tests/fuzz/run.sh replay BUILD_DIR [fuzz_name...]
#     What CI runs (scripts/test-hardened.sh): each target once over every file of its committed
#     corpus, tests/fuzz/corpus/<name>/ (the seeds and every regression-* finding), and nothing
#     else: no mutation, so every run tries the same inputs and gives the same verdict. A target
#     without a corpus fails (each needs seeds, and its findings belong there).
#
#   tests/fuzz/run.sh fuzz BUILD_DIR SECONDS [fuzz_name...]
#     The open-ended runs (scripts/fuzz-long.sh): mutation for SECONDS per target, from a copy of
#     the corpus (the repository is not modified). Findings (crash-*, leak-*, timeout-*, oom-*)
#     are kept in BUILD_DIR/fuzz-work/<name>/findings/, the run's log in BUILD_DIR/fuzz-work/<name>/run.log.
#
# Both modes use the same limits. A dictionary tests/fuzz/<name>.dict is used when present.
set -euo pipefail
usage() { echo "usage: $0 replay BUILD_DIR [fuzz_name...] | fuzz BUILD_DIR SECONDS [fuzz_name...]" >&2; exit 2; }
[ $# -ge 2 ] || usage
mode=$1
case "$mode" in
  replay) build=$(cd "$2" && pwd); shift 2 ;;  # absolute: fuzz_cli_args runs inside a folder of its own
  fuzz) [ $# -ge 3 ] || usage; build=$(cd "$2" && pwd) seconds=$3; shift 3 ;;
  *) usage ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$build"/tests/fuzz/fuzz_*; do [ -x "$f" ] && targets+=("$(basename "$f")"); done
fi
[ ${#targets[@]} -gt 0 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }

# Limits: 20 s per input; 3 GB of resident memory. The EXR targets prove an allocation bound:
# their reader has a 16 MB budget, and no single allocation may exceed that plus OpenImageIO's
# 64 MB scanline conversion buffer, plus 16 MB (an out-of-memory finding otherwise).
limits_of() {
  local limits=(-timeout=20 -rss_limit_mb=3072)
  case "$1" in exr_header | exr_windows) limits+=(-malloc_limit_mb=96) ;; esac
  echo "${limits[@]}"
}

failed=0
for t in "${targets[@]}"; do
  name=${t#fuzz_}
  work="$build/fuzz-work/$name"
  mkdir -p "$work"
  seed="$here/corpus/$name"
  read -r -a limits <<<"$(limits_of "$name")"
  log="$work/$mode.log"
  if [ "$mode" = replay ]; then
    mapfile -t inputs < <([ -d "$seed" ] && find "$seed" -type f | sort)
    if [ ${#inputs[@]} -eq 0 ]; then
      echo "fuzz $name: FAILED: no committed corpus in $seed"
      failed=1
      continue
    fi
    if "$build/tests/fuzz/$t" "${limits[@]}" "${inputs[@]}" >"$log" 2>&1; then
      echo "fuzz $name: ok, replayed ${#inputs[@]} committed inputs"
    else
      echo "fuzz $name: FAILED on a committed input; log tail ($log):"
      tail -30 "$log"
      failed=1
    fi
    continue
  fi
  mkdir -p "$work/corpus" "$work/findings"
  [ -d "$seed" ] && cp -n "$seed"/* "$work/corpus/" 2>/dev/null || true
  dict=()
  [ -f "$here/$name.dict" ] && dict=(-dict="$here/$name.dict")
  if "$build/tests/fuzz/$t" "${dict[@]}" -max_total_time="$seconds" "${limits[@]}" -print_final_stats=1 \
       -artifact_prefix="$work/findings/" "$work/corpus" >"$log" 2>&1; then
    runs=$(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}')
    cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
    peak=$(grep -m1 'stat::peak_rss_mb' "$log" | awk '{print $2}')
    echo "fuzz $name: ok, ${runs:-?} executions in ${seconds}s, coverage ${cov:-?} edges, corpus $(ls "$work/corpus" | wc -l) inputs, peak RSS ${peak:-?} MB"
  else
    echo "fuzz $name: FAILED (finding in $work/findings/); log tail ($log):"
    tail -30 "$log"
    failed=1
  fi
done
exit $failed
