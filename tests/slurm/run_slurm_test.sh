#!/usr/bin/env bash
# End-to-end test of scripts/slurm/cgtmo-slurm on a real one-node Slurm cluster started here:
# munge, slurmctld and slurmd on loopback with a private config and state folders. The daemons
# are stopped by their pid files on exit. Every sbatch call goes through a logging wrapper first on
# PATH, which refuses to run inside a job. Four runs:
#  1. 12 frames in 4-frame chunks (3 tasks), 2 retries, relative patterns and --colorconfig, the
#     tasks started in / (--chdir): one task SIGKILLed after its first frame (test hook). The
#     killed chunk runs again in attempt 1, the others are found complete; each sbatch call (4, all
#     at submission) carries --account, --qos, --time, --mem, --cpus-per-task and a --sbatch-option,
#     and Slurm shows the time limit, memory, account and comment; every output equals a local
#     'cgtmo apply'; a second run into the same --state is refused.
#  2. Two runs at once into one output folder (frames 1-6 and 7-12), each with its own state
#     folder; both end well and every frame is right.
#  3. A run whose jobs are cancelled: --wait notices by job ID and exits 1.
#  4. A run with another operator (--op agx) over the outputs of run 1, frames 1-13 with no input
#     for 13: every frame must be redone, and 13 reported as 'no input', not failed. This needs a
#     cgtmo whose outputs record the settings they were made with and whose --dry-run says
#     'missing' for an absent input (with a cgtmo that only compares file times, run 4 fails).
#  5. Every path with hostile bytes: the input and output folders, the file names, --state,
#     --cgtmo and a relative --colorconfig each hold a newline (also at the end), quotes, '$(...)',
#     backticks, spaces, '%a' and a byte that is not UTF-8. Beside them lie the same names
#     without those bytes, holding another shot's frame: every output lands in the folder named,
#     byte-equal to a local run, the other shot's frame is untouched, the command file reads back
#     byte for byte, nothing runs from a name, and the report counts 3 of 3.
#  6. Refused before anything is queued, with one line and no state folder: frames 1-240 of a
#     shot on disk as 1001-1006 (cgtmo's own plan check, in its words, exit 1), and a state
#     folder with a backslash (Slurm drops it from log paths).
#   run_slurm_test.sh CGTMO_BINARY WORK_DIR
# Exit 77 (ctest: skipped) when not root or Slurm/munge are not installed.
set -euo pipefail
cgtmo=$(readlink -f "$1")
work=$(mkdir -p "$2" && cd "$2" && pwd)
repo=$(cd "$(dirname "$0")/../.." && pwd)

if [ "$(id -u)" -ne 0 ] || ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  echo "SKIP: needs root and Debian's slurm-wlm and munge (scripts/install-deps.sh installs them)"
  exit 77
fi

rm -rf "$work" && mkdir -p "$work"/{state,spool,log,frames,out,local}
export SLURM_CONF="$work/slurm.conf"
pids=()
cleanup() {
  for f in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
  done
  [ -f "$work/munge/munged.pid" ] && kill "$(cat "$work/munge/munged.pid")" 2>/dev/null || true
  sleep 0.5
}
trap cleanup EXIT

# munge: a key of our own and a daemon on a private socket.
mkdir -p /etc/munge "$work/munge"
key="$work/munge/munge.key"
dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
chown munge:munge "$key" "$work/munge" && chmod 400 "$key" && chmod 700 "$work/munge"
socket="$work/munge/munge.socket"
runuser -u munge -- /usr/sbin/munged --key-file="$key" --socket="$socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/seed" --force
for _ in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done

host=$(hostname -s)
cpus=$(nproc)
mem=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 * 8 / 10 ))
cat > "$SLURM_CONF" <<CONF
ClusterName=cgtmo-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MinJobAge=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=cgtmo Nodes=$host Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES
CONF
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for i in $(seq 100); do
  sinfo -h -o '%t' 2>/dev/null | grep -qE '^(idle|mix)' && break
  [ "$i" -eq 100 ] && { echo "FAIL: node never became idle"; sinfo || true; tail -20 "$work/log/slurmctld.log"; exit 1; }
  sleep 0.2
done
echo "cluster up: $(sinfo -h -o '%P %t %D')"

# A 12-frame sequence of small multilayer renders.
/usr/bin/python3 "$repo/tests/cli/make_inputs.py" "$work/gen"
for f in $(seq 1 12); do cp "$work/gen/hdr.exr" "$work/frames/shot.$(printf %04d "$f").exr"; done

# sbatch behind a wrapper that logs each call (its words, each between spaces, one line a call) and
# refuses any call from inside a job: retries must not need sbatch on a compute node.
real_sbatch=$(command -v sbatch)
mkdir -p "$work/bin"
cat > "$work/bin/sbatch" <<WRAPPER
#!/usr/bin/env bash
log=\${CGTMO_TEST_SBATCH_LOG:-$work/sbatch.log}
if [ -n "\${SLURM_JOB_ID:-}" ]; then
  echo "INSIDE JOB \$SLURM_JOB_ID:\$(printf ' %s' "\$@") " >> "\$log"
  echo "sbatch: refused inside a job (test wrapper)" >&2
  exit 1
fi
echo "\$(printf ' %s' "\$@") " >> "\$log"
exec $real_sbatch "\$@"
WRAPPER
chmod +x "$work/bin/sbatch"
export PATH="$work/bin:$PATH"
unset SLURM_JOB_ID CGTMO_SLURM_TEST_KILL_TASK

fail() { echo "FAIL: $*"; exit 1; }
cgtmo_slurm() { timeout 300 "$repo/scripts/slurm/cgtmo-slurm" --cgtmo "$cgtmo" "$@"; }
# Relative from $work, where the runs start: the command file must hold it absolute.
config_rel=$(realpath --relative-to="$work" "$repo/ocio_config/config.ocio")
config_abs=$(readlink -f "$repo/ocio_config/config.ocio")
# Local references, one sequence run per operator.
local_run() {
  mkdir -p "$work/local-$1"
  "$cgtmo" apply "$work/frames/shot.####.exr" -o "$work/local-$1/shot.####.png" --frames 1-12 \
    --op "$1" --colorconfig "$config_abs" -q 2>/dev/null
}
# same_frames OP DIR FIRST LAST: frames FIRST..LAST of DIR equal the local run of OP.
same_frames() {
  local f n
  for f in $(seq "$3" "$4"); do
    n=$(printf %04d "$f")
    cmp -s "$work/local-$1/shot.$n.png" "$2/shot.$n.png" || return 1
  done
}
local_run aces-narkowicz
local_run agx
cd "$work"

# --- 1. Options, kill and retry, absolute paths ---------------------------------------------
opts=(--account acct1 --qos normal --time 10 --mem 100 --cpus-per-task 1
      --sbatch-option=--comment=cgtmo-test --sbatch-option --chdir=/)
export CGTMO_SLURM_TEST_KILL_TASK=2 CGTMO_TEST_SBATCH_LOG="$work/sbatch-1.log"
set +e
cgtmo_slurm --frames 1-12 --chunk 4 --retries 2 --wait "${opts[@]}" --state "$work/run" \
  frames/shot.####.exr out/shot.####.png -- --op aces-narkowicz --colorconfig "$config_rel"
rc=$?
set -e
unset CGTMO_SLURM_TEST_KILL_TASK
[ "$rc" -eq 0 ] || { echo "FAIL: cgtmo-slurm exited $rc"; tail -n 40 "$work/run"/*.log 2>/dev/null; exit 1; }
[ -e "$work/run/test-killed-2" ] || fail "the kill hook never fired"
history=$(cat "$work/run/history.txt")
for line in "attempt 0 chunk 2: no result" "attempt 1 chunk 2: ran, rc 0" "attempt 0 chunk 1: ran, rc 0" \
            "attempt 1 chunk 1: already complete" "attempt 2 chunk 2: already complete"; do
  grep -qF "$line" <<< "$history" || { echo "$history"; fail "no '$line' in the history"; }
done
[ -e "$work/run/task-2-attempt1.log" ] || fail "chunk 2 was not retried"
grep -q '^complete' "$work/run/task-1-attempt1.log" || fail "task 1 of attempt 1 did not stop at once"

# Every sbatch call at submission (attempts 0-2 and the report), none from a job, each with the options.
calls=$(cat "$work/sbatch-1.log")
grep -q 'INSIDE JOB' <<< "$calls" && { echo "$calls"; fail "sbatch was called from inside a job"; }
[ "$(wc -l <<< "$calls")" -eq 4 ] || { echo "$calls"; fail "expected 4 sbatch calls, all at submission"; }
while read -r call; do
  for o in --account=acct1 --qos=normal --time=10 --mem=100 --cpus-per-task=1 --comment=cgtmo-test --chdir=/; do
    grep -qF -- " $o " <<< " $call " || fail "sbatch call without $o: $call"
  done
done <<< "$calls"
# What Slurm made of them, on the report job (the last to end, still known: MinJobAge=30). This
# cluster keeps no accounting database, so it keeps the account but drops the QOS ((null)): the
# QOS is checked in the sbatch calls only.
[ "$(wc -l < "$work/run/jobs")" -eq 4 ] || fail "STATE/jobs does not hold 4 job IDs"
job=$(scontrol show job "$(tail -n 1 "$work/run/jobs")")
for field in TimeLimit=00:10:00 Account=acct1 MinMemoryNode=100M Comment=cgtmo-test WorkDir=/; do
  grep -qE "(^|[[:space:]])$field([[:space:]]|$)" <<< "$job" || { echo "$job"; fail "the report job lacks $field"; }
done
# The command holds absolute paths only (the tasks ran in /).
eval "words=($(cat "$work/run/command"))"
[ "${words[2]}" = "$work/frames/shot.####.exr" ] && [ "${words[4]}" = "$work/out/shot.####.png" ] ||
  fail "patterns not absolute in the command: $(cat "$work/run/command")"
grep -qF -- "--colorconfig $config_abs" "$work/run/command" || fail "--colorconfig not absolute: $(cat "$work/run/command")"

same_frames aces-narkowicz "$work/out" 1 12 || fail "run 1: a frame differs from a local run"
if ls -a "$work/out" | grep -q cgtmo-tmp; then fail "temporary files left in the output folder"; fi

# A state folder that holds a run is not reused, and nothing is submitted.
set +e
cgtmo_slurm --frames 1-12 --state "$work/run" frames/shot.####.exr out/shot.####.png 2> "$work/reuse.err"
rc=$?
set -e
[ "$rc" -eq 2 ] && grep -q 'already holds a run' "$work/reuse.err" || fail "a used --state was not refused (exit $rc)"
[ "$(wc -l < "$work/sbatch-1.log")" -eq 4 ] || fail "a refused run called sbatch"
echo "PASS 1: options reach sbatch and Slurm, 4 sbatch calls at submission, task 2 killed and retried, frames equal local runs"

# --- 2. Two runs at once into one output folder ---------------------------------------------
export CGTMO_TEST_SBATCH_LOG="$work/sbatch-2.log"
mkdir -p "$work/out2"
cgtmo_slurm --frames 1-6 --chunk 3 --retries 1 --wait frames/shot.####.exr out2/shot.####.png \
  -- --op aces-narkowicz --colorconfig "$config_rel" > "$work/run2a.out" 2>&1 &
pa=$!
cgtmo_slurm --frames 7-12 --chunk 3 --retries 1 --wait frames/shot.####.exr out2/shot.####.png \
  -- --op aces-narkowicz --colorconfig "$config_rel" > "$work/run2b.out" 2>&1 &
pb=$!
rca=0 rcb=0
wait "$pa" || rca=$?
wait "$pb" || rcb=$?
[ "$rca" -eq 0 ] && [ "$rcb" -eq 0 ] || { cat "$work/run2a.out" "$work/run2b.out"; fail "concurrent runs exited $rca and $rcb"; }
sa=$(sed -n 's/.*; state in //p' "$work/run2a.out")
sb=$(sed -n 's/.*; state in //p' "$work/run2b.out")
[ -n "$sa" ] && [ -n "$sb" ] && [ "$sa" != "$sb" ] || fail "the concurrent runs did not get state folders of their own ('$sa', '$sb')"
[ "$(dirname "$sa")" = "$work/out2/.cgtmo-slurm" ] && [ "$(dirname "$sb")" = "$work/out2/.cgtmo-slurm" ] ||
  fail "state folders not under the output folder: $sa $sb"
for s in "$sa" "$sb"; do
  grep -q '^cgtmo-slurm report: 6 of 6 frames written' "$s/report.txt" || fail "wrong report in $s"
done
same_frames aces-narkowicz "$work/out2" 1 12 || fail "run 2: a frame differs from a local run"
[ "$(wc -l < "$work/sbatch-2.log")" -eq 6 ] || fail "run 2: expected 6 sbatch calls"
echo "PASS 2: two runs at once into one output folder, state in $(basename "$sa") and $(basename "$sb")"

# --- 3. --wait follows job IDs: cancelled jobs end the wait with exit 1 -------------------------
export CGTMO_TEST_SBATCH_LOG="$work/sbatch-3.log"
mkdir -p "$work/out3"
cgtmo_slurm --frames 1-3 --retries 0 --wait --state "$work/run3" --sbatch-option=--begin=now+3600 \
  frames/shot.####.exr out3/shot.####.png > "$work/run3.out" 2> "$work/run3.err" &
p3=$!
for i in $(seq 100); do
  grep -q 'state in' "$work/run3.out" && break
  [ "$i" -eq 100 ] && fail "run 3 never submitted"
  sleep 0.2
done
mapfile -t jobs3 < "$work/run3/jobs"
[ "${#jobs3[@]}" -eq 2 ] || fail "run 3: expected 2 job IDs"
scancel "${jobs3[@]}"
rc3=0
wait "$p3" || rc3=$?
[ "$rc3" -eq 1 ] && grep -q 'ended without a final report' "$work/run3.err" ||
  { cat "$work/run3.out" "$work/run3.err"; fail "run 3: --wait did not notice its cancelled jobs (exit $rc3)"; }
echo "PASS 3: --wait notices that the run's jobs are gone (cancelled) and exits 1"

# --- 4. Another setting over existing outputs redoes every frame; a frame without input ---------
# Frame 13 has no input: the report names it apart from failed frames, and the run exits 1.
export CGTMO_TEST_SBATCH_LOG="$work/sbatch-4.log"
set +e
cgtmo_slurm --frames 1-13 --chunk 7 --retries 0 --wait --state "$work/run4" frames/shot.####.exr out/shot.####.png \
  -- --op agx --colorconfig "$config_rel"
rc=$?
set -e
same_frames agx "$work/out" 1 12 ||
  fail "run 4: frames made with --op aces-narkowicz were kept after --op agx (the cgtmo binary must redo outputs made with other settings)"
[ "$rc" -eq 1 ] || fail "run 4 exited $rc, not 1 (frame 13 has no input)"
grep -qx 'no input: 13' "$work/run4/report.txt" && ! grep -q '^failed frames' "$work/run4/report.txt" &&
  grep -q '^cgtmo-slurm report: 12 of 13 frames written' "$work/run4/report.txt" ||
  fail "run 4: frame 13 not reported as 'no input' alone (the cgtmo binary's --dry-run must say 'missing')"
echo "PASS 4: --op agx over aces-narkowicz outputs redid every frame; frame 13 reported without input"

# --- 5. Hostile bytes in every path -------------------------------------------------------------
# A newline at the end was dropped by $(...): the tasks wrote into 'out5/', over another shot.
export CGTMO_TEST_SBATCH_LOG="$work/sbatch-5.log"
h=$' q\'"d" $(touch PWNED1) `touch PWNED2` %a \xff\n'
mkdir -p "$work/in5$h" "$work/out5$h" "$work/out5" "$work/bin$h" "$work/cfg$h" "$work/local5$h"
for f in 1 2 3; do cp "$work/frames/shot.000$f.exr" "$work/in5$h/sh$h.000$f.exr"; done
ln -s "$cgtmo" "$work/bin$h/cgtmo"
cp "$config_abs" "$work/cfg$h/config.ocio"
ln -sfn "$repo/luts" "$work/luts"  # the config's search_path, ../luts
printf 'another shot\n' > "$work/out5/o.0002.png"
cp "$work/out5/o.0002.png" "$work/other-shot.png"
set +e
(cd "$work" && timeout 300 "$repo/scripts/slurm/cgtmo-slurm" --cgtmo "bin$h/cgtmo" --frames 1-3 --chunk 2 --retries 0 \
  --wait --state "state5$h" "in5$h/sh$h.####.exr" "out5$h/o$h.####.png" -- --op agx --colorconfig "cfg$h/config.ocio") \
  > "$work/run5.out" 2>&1
rc=$?
set -e
[ "$rc" -eq 0 ] || { cat "$work/run5.out"; tail -n 20 "$work/state5$h"/*.log 2>/dev/null; fail "run 5 exited $rc"; }
"$cgtmo" apply "$work/in5$h/sh$h.####.exr" -o "$work/local5$h/o$h.####.png" --frames 1-3 --op agx \
  --colorconfig "$work/cfg$h/config.ocio" -q 2>/dev/null
for f in 1 2 3; do
  cmp -s "$work/local5$h/o$h.000$f.png" "$work/out5$h/o$h.000$f.png" || fail "run 5: frame $f not in the folder named, or not as a local run"
done
cmp -s "$work/other-shot.png" "$work/out5/o.0002.png" || fail "run 5: the other shot's frame in 'out5' was overwritten"
[ "$(ls -A "$work/out5")" = o.0002.png ] || fail "run 5: written into 'out5': $(ls -A "$work/out5")"
[ -z "$(find "$work" / -maxdepth 1 -name 'PWNED*'; find "$work" -name 'PWNED*')" ] || fail "run 5: a name was run as a command"
# The command file reads back as the very bytes of every path (newlines, quotes, non-UTF-8).
eval "words=($(cat "$work/state5$h/command"))"
expect=("$work/bin$h/cgtmo" apply "$work/in5$h/sh$h.####.exr" -o "$work/out5$h/o$h.####.png" --op agx
        --colorconfig "$work/cfg$h/config.ocio")
[ "${#words[@]}" -eq "${#expect[@]}" ] || fail "run 5: the command has ${#words[@]} words, not ${#expect[@]}"
for i in "${!expect[@]}"; do
  [ "${words[i]}" = "${expect[i]}" ] || fail "run 5: word $i of the command is $(printf %q "${words[i]}")"
done
grep -qx 'cgtmo-slurm report: 3 of 3 frames written' "$work/state5$h/report.txt" ||
  fail "run 5: report: $(head -n 1 "$work/state5$h/report.txt")"
[ -s "$work/state5$h/task-1-attempt0.log" ] && [ -e "$work/state5$h/report.log" ] || fail "run 5: logs not in the state folder"
echo "PASS 5: newlines, quotes, \$(...), backticks, spaces, %a and a non-UTF-8 byte in every path: frames where named"

# --- 6. Refused before anything is queued -------------------------------------------------------
export CGTMO_TEST_SBATCH_LOG="$work/sbatch-6.log"
mkdir -p "$work/shot6" "$work/out6"
for f in 1001 1002 1003 1004 1005 1006; do cp "$work/frames/shot.0001.exr" "$work/shot6/s.$f.exr"; done
set +e
cgtmo_slurm --frames 1-240 shot6/s.####.exr out6/s.####.png > "$work/run6.out" 2> "$work/run6.err"
rc=$?
"$cgtmo" apply shot6/s.####.exr -o out6/s.####.png --frames 1-240 2> "$work/local6.err"
set -e
local_msg=$(sed 's/^cgtmo apply: error: //' "$work/local6.err")
[ "$rc" -eq 1 ] && [ "$(wc -l < "$work/run6.err")" -eq 1 ] &&
  grep -qxF "cgtmo-slurm: error: frames 1-240 of '$work/shot6/s.####.exr' not found (on disk: 1001-1006)" "$work/run6.err" ||
  { cat "$work/run6.err"; fail "run 6: frames 1-240 of 1001-1006 not refused in one line with exit 1 (exit $rc)"; }
[ "$local_msg" = "frames 1-240 of 'shot6/s.####.exr' not found (on disk: 1001-1006)" ] || fail "run 6: local apply says '$local_msg'"
set +e
cgtmo_slurm --frames 1001-1006 --state 'state6\x' shot6/s.####.exr out6/s.####.png > "$work/run6b.out" 2> "$work/run6b.err"
rc=$?
set -e
[ "$rc" -eq 2 ] && [ "$(wc -l < "$work/run6b.err")" -eq 1 ] && grep -q 'holds a backslash' "$work/run6b.err" ||
  { cat "$work/run6b.err"; fail "run 6: a state folder with a backslash was not refused (exit $rc)"; }
[ ! -e "$work/sbatch-6.log" ] || fail "run 6: sbatch was called: $(cat "$work/sbatch-6.log")"
[ -z "$(ls -A "$work/out6")" ] && [ ! -e "$work/state6\x" ] || fail "run 6: a refused run left files: $(ls -A "$work/out6")"
echo "PASS 6: frames 1-240 of a shot on disk as 1001-1006 and a backslash in --state refused at once, nothing queued"
echo "PASS: cgtmo-slurm on a one-node Slurm cluster"
