#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine and runs every test (what CI runs):
#   1. the Release build's suite (ctest): unit, golden-file CLI, Blender, OCIO apps, Slurm, faults,
#      the installed tree; then the Debian package installed with dpkg and removed;
#   2. the same suite built with AddressSanitizer + UndefinedBehaviorSanitizer, and a short run of
#      every fuzzer (scripts/test-hardened.sh; CGTMO_SKIP_HARDENED=1 skips it locally).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)" --timeout 1500
# The Debian package: built, installed with dpkg, run, removed (scripts/test-package.sh).
bash scripts/test-package.sh "$BUILD_DIR"
if [ "${CGTMO_SKIP_HARDENED:-0}" != 1 ]; then
  bash scripts/test-hardened.sh
fi
