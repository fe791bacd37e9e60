#!/usr/bin/env bash
# The open-ended fuzzing runs (docs/hardening.md, "Fuzzing"), apart from CI: a mutation run that
# finds something new would fail CI by chance, so CI only replays the committed corpus
# (tests/fuzz/run.sh replay). This configures the sanitizer build as scripts/test-hardened.sh does
# (clang 14, ASan + UBSan; FUZZ_BUILD_DIR, default build-asan/, shared with it), builds the fuzz
# targets alone, and runs each for SECONDS (default 600) from a copy of its
# corpus, JOBS at a time (default 2), then prints one line per target to record in
# docs/hardening.md. A finding is kept under FUZZ_BUILD_DIR/fuzz-work/<name>/findings/: fix it,
# add it to tests/fuzz/corpus/<name>/ as regression-<what>, and add a unit test.
#   scripts/fuzz-long.sh [SECONDS] [fuzz_name...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
[ $# -gt 0 ] && shift
build=${FUZZ_BUILD_DIR:-build-asan}
jobs=${JOBS:-2}
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in tests/fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
CXX=clang++-14 CC=clang-14 cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCGTMO_FUZZ=ON \
  -DCGTMO_BUILD_PYTHON=OFF -DCGTMO_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1
export LSAN_OPTIONS=suppressions=$(pwd)/tests/fuzz/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
echo "fuzzing ${#targets[@]} targets for ${seconds}s each, $jobs at a time, from $(date -u '+%Y-%m-%d %H:%M UTC')"
mkdir -p "$build/fuzz-work"
pids=() failed=0
for t in "${targets[@]}"; do
  bash tests/fuzz/run.sh fuzz "$build" "$seconds" "$t" >"$build/fuzz-work/$t.result" 2>&1 &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for p in "${pids[@]}"; do wait "$p" || failed=1; done
for t in "${targets[@]}"; do cat "$build/fuzz-work/$t.result"; done
echo "done at $(date -u '+%Y-%m-%d %H:%M UTC'); load average $(cut -d' ' -f1-3 /proc/loadavg)"
exit $failed
