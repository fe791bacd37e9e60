#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine and runs every test (what CI runs):
#   1. the Release build's suite (ctest): unit, golden-file CLI, Blender, OCIO apps, Slurm, faults,
#      the installed tree; then the Debian package installed with dpkg and removed;
#   2. the library built without its x86 SIMD kernels (-DCGTMO_SIMD=OFF, as on a CPU other than
#      x86-64) and the tests of the code that uses them (ctest label simd: filters, operators,
#      curve tables, the dispatcher), at the baseline level;
#   3. the same suite built with AddressSanitizer + UndefinedBehaviorSanitizer, and a short run of
#      every fuzzer (scripts/test-hardened.sh; CGTMO_SKIP_HARDENED=1 skips it locally).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)" --timeout 1500
# The Debian package: built, installed with dpkg, run, removed (scripts/test-package.sh).
bash scripts/test-package.sh "$BUILD_DIR"
nosimd="${BUILD_DIR}-nosimd"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B "$nosimd" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCGTMO_SIMD=OFF \
  -DCGTMO_BUILD_PYTHON=OFF -DCGTMO_BUILD_BENCH=OFF >/dev/null
cmake --build "$nosimd" --parallel "$(nproc)" --target test_filters test_operators test_curve_table test_util
ctest --test-dir "$nosimd" -L simd --output-on-failure --parallel "$(nproc)" --timeout 1500
if [ "${CGTMO_SKIP_HARDENED:-0}" != 1 ]; then
  bash scripts/test-hardened.sh
fi
