#!/usr/bin/env bash
# The hardening half of the test run (docs/hardening.md): the whole test suite built with
# AddressSanitizer + UndefinedBehaviorSanitizer (clang), then every fuzzer replayed over its
# committed corpus (seeds and regression inputs), without mutation: the same verdict on every run.
# The open-ended mutation runs are scripts/fuzz-long.sh, apart from CI.
# The Python module and Blender add-on are left out of this build: an ASan-instrumented module
# cannot load into an uninstrumented python3 or Blender; their tests run in the normal build.
# docs/hardening.md lists what runs here and what does not.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${ASAN_BUILD_DIR:-build-asan}
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
CXX=clang++-14 CC=clang-14 cmake -S . -B "$BUILD_DIR" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCGTMO_FUZZ=ON -DCGTMO_BUILD_PYTHON=OFF -DCGTMO_BUILD_BENCH=OFF >/dev/null
cmake --build "$BUILD_DIR" --parallel "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export LSAN_OPTIONS=suppressions=$(pwd)/tests/fuzz/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Two staleness checks regenerate committed files (the LUTs and docs/lut-accuracy.md, docs/quality.md's
# cornell rows) and compare them byte for byte with what the Release build (GCC) made; another
# compiler may round a last digit differently, so they run in the Release build only.
ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)" --timeout 1500 --label-exclude "plugins|python" \
  -E "^(bake_committed_files_are_current|QualityDoc\.OneSceneRescoredGivesItsRows)$"
bash tests/fuzz/run.sh replay "$BUILD_DIR"
