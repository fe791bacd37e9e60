#!/usr/bin/env bash
# End-to-end test of scripts/slurm/cgtmo-slurm on a real one-node Slurm cluster started here:
# munge, slurmctld and slurmd on loopback with a private config and state folders. Submits a
# 12-frame sequence in 4-frame chunks (3 tasks), SIGKILLs one task after its first frame (test hook), waits, and checks
# that the killed chunk was retried and every output equals a local 'cgtmo apply'. The daemons
# are stopped by their pid files on exit.
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

export CGTMO_SLURM_TEST_KILL_TASK=2
set +e
timeout 300 "$repo/scripts/slurm/cgtmo-slurm" --cgtmo "$cgtmo" --frames 1-12 --chunk 4 --retries 2 --wait \
  --state "$work/run" "$work/frames/shot.####.exr" "$work/out/shot.####.png" -- --op aces-narkowicz
rc=$?
set -e
[ "$rc" -eq 0 ] || { echo "FAIL: cgtmo-slurm exited $rc"; cat "$work/run"/*.log 2>/dev/null | tail -40; exit 1; }
[ -e "$work/run/test-killed-2" ] || { echo "FAIL: the kill hook never fired"; exit 1; }
grep -q "incomplete: 2" "$work/run/history.txt" || { echo "FAIL: chunk 2 was not seen incomplete"; cat "$work/run/history.txt"; exit 1; }
ls "$work/run"/task-2-attempt1.log >/dev/null || { echo "FAIL: chunk 2 was not retried"; exit 1; }

# Every frame equals a local run, and nothing partial is left.
for f in $(seq 1 12); do
  n=$(printf %04d "$f")
  "$cgtmo" apply "$work/frames/shot.$n.exr" -o "$work/local/shot.$n.png" --op aces-narkowicz -q 2>/dev/null
  cmp -s "$work/local/shot.$n.png" "$work/out/shot.$n.png" || { echo "FAIL: frame $n differs from a local run"; exit 1; }
done
if ls -a "$work/out" | grep -q cgtmo-tmp; then echo "FAIL: temporary files left in the output folder"; exit 1; fi
echo "PASS: 12 frames on Slurm in 3 array tasks, task 2 killed mid-way and retried; all equal to local runs"
cat "$work/run/report.txt"
