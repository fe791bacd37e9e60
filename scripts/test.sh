#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine and runs every test (what CI runs):
#   1. the Release build's suite (ctest): unit, golden-file CLI, Blender, OCIO apps, Slurm, faults,
#      the installed tree;
#   2. the Debian package: built, installed with dpkg, run, removed (scripts/test-package.sh);
#   3. the library built without its x86 SIMD kernels (-DCGTMO_SIMD=OFF, as on a CPU other than
#      x86-64) and the tests of the code that uses them (ctest label simd), at the baseline level;
#   4. the committed generated files re-made on an emulated other CPU: glibc's FMA/AVX2/AVX-512
#      variants masked and CGTMO_ISA=baseline, byte for byte (scripts/check-reproducible.sh);
#   5. the same suite built with AddressSanitizer + UndefinedBehaviorSanitizer, and a replay of every
#      fuzzer's committed corpus (scripts/test-hardened.sh; CGTMO_SKIP_HARDENED=1 skips it locally).
# A failing stage does not stop the others: the run ends with one line per stage and exits non-zero
# when any failed, so one run shows everything that is broken. Setting up (packages, the build) is
# the exception: nothing can be tested without it.
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
export BUILD_DIR
start=$(date +%s)
bash scripts/install-deps.sh || exit 1
bash scripts/build.sh || exit 1

results=()
failed=0
# stage NAME COMMAND...: runs it, records "NAME: passed|FAILED (exit N), M min S s".
stage() {
  local name=$1 t0=$SECONDS rc
  shift
  echo "=== test.sh: $name"
  "$@"
  rc=$?
  local took=$((SECONDS - t0))
  if [ $rc -eq 0 ]; then
    results+=("passed  $name ($((took / 60)) min $((took % 60)) s)")
  else
    results+=("FAILED  $name: exit $rc ($((took / 60)) min $((took % 60)) s)")
    failed=1
  fi
}

release_suite() {
  ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)" --timeout 1500
}
no_simd_suite() {
  local nosimd="${BUILD_DIR}-nosimd" generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S . -B "$nosimd" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCGTMO_SIMD=OFF \
    -DCGTMO_BUILD_PYTHON=OFF -DCGTMO_BUILD_BENCH=OFF >/dev/null &&
    cmake --build "$nosimd" --parallel "$(nproc)" --target test_filters test_operators test_curve_table test_util &&
    ctest --test-dir "$nosimd" -L simd --output-on-failure --parallel "$(nproc)" --timeout 1500
}

stage "Release suite (ctest)" release_suite
stage "Debian package" bash scripts/test-package.sh "$BUILD_DIR"
stage "no-SIMD build (ctest -L simd)" no_simd_suite
stage "committed files on an emulated other CPU" bash scripts/check-reproducible.sh "$BUILD_DIR"
if [ "${CGTMO_SKIP_HARDENED:-0}" != 1 ]; then
  stage "sanitizers and fuzz corpus replay" bash scripts/test-hardened.sh
fi

total=$(($(date +%s) - start))
echo "=== test.sh: summary ($((total / 60)) min $((total % 60)) s in all, install and build included)"
printf '  %s\n' "${results[@]}"
exit $failed
