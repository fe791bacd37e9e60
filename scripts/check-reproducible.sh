#!/usr/bin/env bash
# The committed generated files, re-made as another x86-64 CPU would make them, compared byte for
# byte (a stage of scripts/test.sh; docs/numerics.md says why they can be). The suite's staleness
# checks run again with:
#   - glibc's CPU-specific variants masked (FMA, AVX2, AVX-512: GLIBC_TUNABLES) and the library's own
#     kernels at the baseline level (CGTMO_ISA=baseline): a CPU older than this one;
#   - the kernels at each other level this CPU has (CGTMO_ISA=avx2): the plain suite runs the best.
# The checks: bake_committed_files_are_current (luts/, ocio_config/, docs/lut-accuracy.md),
# QualityDoc.* (docs/quality.md's inputs and cornell's rows), cli_golden_* (tests/cli/ref/, bit for
# bit). --full also regenerates the whole of docs/quality.md on the emulated CPU (minutes).
#   usage: scripts/check-reproducible.sh [--full] [BUILD_DIR]        (default: build)
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
full=0
[ "${1:-}" = --full ] && { full=1; shift; }
build=$(cd "${1:-${BUILD_DIR:-build}}" && pwd)
cgtmo=$build/apps/cgtmo/cgtmo
[ -x "$cgtmo" ] || { echo "check-reproducible: no $cgtmo (build first: scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/cgtmo-repro.XXXXXX")
trap 'rm -rf "$work"' EXIT

masked="glibc.cpu.hwcaps=-AVX2,-FMA,-AVX512F,-AVX512DQ,-AVX512BW,-AVX512VL"
# The tunable's names change between glibc versions and an unknown one is ignored silently: say
# whether it took effect here (it does nothing on a CPU that has none of these features).
ldso=$(ls /lib64/ld-linux-x86-64.so.2 2>/dev/null || true)
if [ -n "$ldso" ] && [ "$(GLIBC_TUNABLES=$masked "$ldso" --list-diagnostics 2>/dev/null | grep -c 'cpu_features.*active')" -gt 0 ]; then
  if diff -q <("$ldso" --list-diagnostics | grep 'cpu_features.*active') \
             <(GLIBC_TUNABLES=$masked "$ldso" --list-diagnostics | grep 'cpu_features.*active') >/dev/null; then
    echo "check-reproducible: note: GLIBC_TUNABLES=$masked changes nothing on this CPU"
  else
    echo "check-reproducible: emulating a CPU without FMA, AVX2 and AVX-512 (GLIBC_TUNABLES=$masked)"
  fi
fi

failed=0
# suite TAG ENV...: the staleness checks under ENV.
checks='^(bake_committed_files_are_current|QualityDoc\..*|cli_make_inputs|cli_golden_.*)$'
suite() {
  local tag=$1
  shift
  if env "$@" ctest --test-dir "$build" -R "$checks" --output-on-failure --timeout 1800 >"$work/$tag.log" 2>&1; then
    echo "  ok      $tag: $(grep -Eo '[0-9]+ tests passed|tests passed, 0 tests failed out of [0-9]+' "$work/$tag.log" | tail -1)"
  else
    echo "  FAILED  $tag: $(grep -E 'Failed|\*\*\*' "$work/$tag.log" | head -5 | tr -s ' ' | tr '\n' ';')"
    sed -n '/The following tests FAILED/,$p' "$work/$tag.log"
    failed=1
  fi
}

suite "emulated older CPU (tunables, CGTMO_ISA=baseline)" GLIBC_TUNABLES="$masked" CGTMO_ISA=baseline
# A level this CPU lacks falls back to a lower one, and the best one is the plain suite's.
grep -qw avx512f /proc/cpuinfo && suite "CGTMO_ISA=avx2" CGTMO_ISA=avx2

if [ $full -eq 1 ]; then
  q=$work/quality
  mkdir -p "$q/tests" "$q/docs"
  ln -s "$root/tests/scenes" "$q/tests/scenes"  # the same relative paths the committed file names
  if (cd "$q" && GLIBC_TUNABLES=$masked CGTMO_ISA=baseline "$cgtmo" eval --scenes tests/scenes --write docs/quality.md \
        >"$q.log" 2>&1) && cmp -s "$q/docs/quality.md" "$root/docs/quality.md"; then
    echo "  ok      emulated older CPU: the whole of docs/quality.md"
  else
    echo "  FAILED  emulated older CPU: docs/quality.md differs or eval failed ($(tail -1 "$q.log"))"
    failed=1
  fi
fi

[ $failed -eq 0 ] && echo "check-reproducible: every committed generated file checked is the same bytes here" ||
  echo "check-reproducible: FAILED (regenerate with the command each file names, on any machine)"
exit $failed
