#!/usr/bin/env bash
# How many frames of a sequence run at once follows what the process is allotted, not the
# machine's core count: under `taskset` (one CPU in the affinity mask) and with
# SLURM_CPUS_PER_TASK=1 a two-frame run says "1 at a time" and why in its summary.
#   sequence_allocation.sh CGTMO_BINARY INPUTS_DIR WORK_DIR     (exit 77: skipped, no taskset)
set -uo pipefail
source "$(dirname "$(readlink -f "$0")")/bounded.sh"
cgtmo=$(readlink -f "$1")
inputs=$(readlink -f "$2")
work=$3
command -v taskset >/dev/null || { echo "skipped: taskset (util-linux) not found"; exit 77; }
rm -rf "$work" && mkdir -p "$work/in" "$work/out" && cd "$work" || exit 1
cp "$inputs/hdr.exr" in/shot.0001.exr && cp "$inputs/hdr.exr" in/shot.0002.exr || exit 1
# The first CPU this test may run on (CPU 0 may be outside a cpuset).
first_cpu=$(taskset -cp $$ | sed 's/.*: *//' | grep -oE '^[0-9]+')
taskset -c "$first_cpu" true || { echo "skipped: taskset -c $first_cpu cannot run here"; exit 77; }
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
# run NAME OUT_PREFIX COMMAND_PREFIX... -- ARGS...: a two-frame apply; its summary in summary.txt.
# Slurm's variables of the environment the test runs in are removed, so only the case's count.
run() {
  local name=$1 out=$2; shift 2
  local prefix=()
  while [ "$1" != "--" ]; do prefix+=("$1"); shift; done
  shift
  bounded 60 env -u SLURM_CPUS_PER_TASK -u SLURM_MEM_PER_NODE -u SLURM_MEM_PER_CPU "${prefix[@]}" \
    "$cgtmo" apply 'in/shot.####.exr' -o "out/$out.####.png" --op reinhard "$@" >stdout.txt 2>stderr.txt
  local rc=$?
  grep 'frames in' stderr.txt >summary.txt
  check "$name: exit 0 (got $rc)" "[ $rc -eq 0 ]"
  check "$name: both frames written" "[ -s out/$out.0001.png ] && [ -s out/$out.0002.png ]"
  echo "     | $(cat summary.txt)"
}

# What the process gets without any of the limits below (a cgroup quota of the test's own
# environment may already hold it to one CPU).
cpus=$(env -u SLURM_CPUS_PER_TASK "$cgtmo" info --allocation | sed -n 's/^cpus: \([0-9]*\).*/\1/p')
check "info --allocation prints the CPUs" "[ -n '$cpus' ] && [ '$cpus' -ge 1 ]"
echo "     | allotted without limits: $cpus CPUs"

run "taskset one CPU" t taskset -c "$first_cpu" --
check "taskset one CPU: 1 at a time, from the affinity mask" "grep -q '(1 at a time: 1 CPU from the affinity mask)' summary.txt"

run "SLURM_CPUS_PER_TASK=1" s env SLURM_CPUS_PER_TASK=1 --
check "SLURM_CPUS_PER_TASK=1: 1 at a time" "grep -q '(1 at a time' summary.txt"
if [ "${cpus:-1}" -ge 2 ]; then
  check "SLURM_CPUS_PER_TASK=1: says why" "grep -q '(1 at a time: 1 CPU from SLURM_CPUS_PER_TASK)' summary.txt"
  # The cases above are not what any run prints: without a limit, two at a time.
  run "no limit" n env --
  check "no limit: 2 at a time" "grep -q '(2 at a time)' summary.txt"
  run "SLURM_CPUS_PER_TASK=abc is ignored" g env SLURM_CPUS_PER_TASK=abc --
  check "SLURM_CPUS_PER_TASK=abc: 2 at a time" "grep -q '(2 at a time)' summary.txt"
fi

run "--threads 1" h env -- --threads 1
check "--threads 1: 1 at a time, from --threads" "grep -q '(1 at a time: --threads 1)' summary.txt"

exit $fail
