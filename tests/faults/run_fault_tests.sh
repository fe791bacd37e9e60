#!/usr/bin/env bash
# Output safety under faults (docs/hardening.md). For each fault: the previous output, if any,
# is intact; no partial or temporary file remains; the exit status is non-zero.
#   1. disk full: the output folder is a 512 KB tmpfs;
#   2. read-only output folder: the tmpfs remounted read-only;
#   3. killed during the run: SIGKILL at 12 moments spread over a run's duration;
#   4. a sequence interrupted by SIGINT and SIGTERM: exit 130, nothing partial, a rerun resumes;
#   5. killed between link and rename (strace injects SIGKILL at rename): the next run removes
#      the temporary left behind;
#   6. a bake on a full disk: exit 1 naming the cause; a bake killed (SIGKILL, SIGTERM) at each
#      named point of its staging and commit: the previous LUT and config set stays whole, or
#      (SIGKILL between two renames) the documented mix; the next bake leaves no staging folder;
#   7. bake --into killed (SIGKILL, SIGTERM) at each named point of its staging and commit: the
#      previous config and its set, or the new ones, whole; the next merge leaves nothing else;
#   8. runs in different pid namespaces (colliding pids) writing into one folder: a live run's
#      temporary is never removed, no frame is lost, nothing is left.
# Kills in 6 and 7 land where the program stops itself (CGTMO_TEST_PAUSE_AT), never by timing.
#   run_fault_tests.sh CGTMO_BINARY WORK_DIR
# Exit 77 (ctest: skipped) when tmpfs cannot be mounted here (not root).
set -uo pipefail
cgtmo=$(readlink -f "$1")
work=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work" && work=$(cd "$work" && pwd)
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
only_files() {  # the folder holds exactly these names (hidden files included)
  local dir=$1; shift
  [ "$(ls -A "$dir" | sort | tr '\n' ' ')" = "$(printf '%s\n' "$@" | sort | tr '\n' ' ')" ]
}

# A 1920x1080 render, big enough that encoding its PNG takes a while and needs megabytes.
/usr/bin/python3 - "$work/in.exr" <<'PY'
import sys, numpy as np, OpenImageIO as oiio
h, w = 1080, 1920
rng = np.random.default_rng(7)
img = np.exp2(rng.uniform(-8, 10, (h, w, 3))).astype(np.float32)
spec = oiio.ImageSpec(w, h, 3, oiio.HALF)
out = oiio.ImageOutput.create(sys.argv[1]); out.open(sys.argv[1], spec); out.write_image(img); out.close()
PY
"$cgtmo" apply "$work/in.exr" -o "$work/old.png" --op linear -q
"$cgtmo" apply "$work/in.exr" -o "$work/new.png" --op agx -q
old_sum=$(md5sum < "$work/old.png") new_sum=$(md5sum < "$work/new.png")

mnt="$work/mnt"
mkdir -p "$mnt"
if ! mount -t tmpfs -o size=512k tmpfs "$mnt" 2>/dev/null; then
  echo "SKIP: cannot mount a tmpfs here (needs root)"
  exit 77
fi
trap 'umount "$mnt" 2>/dev/null' EXIT

# 1. Disk full. The previous output is small; the new one does not fit.
"$cgtmo" apply "$work/in.exr" -o "$mnt/out.png" --op linear --exposure -40 -q  # black: a tiny PNG
small_sum=$(md5sum < "$mnt/out.png")
err=$("$cgtmo" apply "$work/in.exr" -o "$mnt/out.png" --op agx -q 2>&1); rc=$?
check "disk full: exit 1" '[ $rc -eq 1 ]'
check "disk full: one-line error naming the cause" '[ "$(echo "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "No space left"'
check "disk full: previous output intact" '[ "$(md5sum < "$mnt/out.png")" = "$small_sum" ]'
check "disk full: nothing else left" 'only_files "$mnt" out.png'

# 2. Read-only folder.
mount -o remount,ro "$mnt"
err=$("$cgtmo" apply "$work/in.exr" -o "$mnt/out.png" --op agx -q 2>&1); rc=$?
check "read-only folder: non-zero exit" '[ $rc -ne 0 ]'
check "read-only folder: error names it" 'echo "$err" | grep -qi "read-only"'
check "read-only folder: previous output intact" '[ "$(md5sum < "$mnt/out.png")" = "$small_sum" ]'
umount "$mnt"

# 3. SIGKILL at moments spread over one run. After each: the output is the old one or the
#    complete new one, and nothing else is in the folder.
dir="$work/kill"
mkdir -p "$dir"
t0=$(date +%s%N); "$cgtmo" apply "$work/in.exr" -o "$dir/probe.png" --op agx -q; t1=$(date +%s%N)
run_ms=$(( (t1 - t0) / 1000000 )); rm -f "$dir/probe.png"
bad=0 old_seen=0 new_seen=0
for i in $(seq 0 11); do
  cp "$work/old.png" "$dir/out.png"
  delay_ms=$(( run_ms * i / 10 ))
  "$cgtmo" apply "$work/in.exr" -o "$dir/out.png" --op agx -q & pid=$!
  sleep "$(printf '0.%03d' "$delay_ms" 2>/dev/null || echo 0)"
  [ "$delay_ms" -ge 1000 ] && sleep $((delay_ms / 1000))
  kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  s=$(md5sum < "$dir/out.png")
  if [ "$s" = "$old_sum" ]; then old_seen=$((old_seen + 1)); elif [ "$s" = "$new_sum" ]; then new_seen=$((new_seen + 1)); else bad=1; fi
  only_files "$dir" out.png || { echo "  left behind after a kill at ${delay_ms} ms: $(ls -A "$dir")"; bad=1; }
done
echo "     (run takes ${run_ms} ms; kills left the old output $old_seen times, the complete new one $new_seen times)"
check "SIGKILL during a run: old or complete new output, nothing partial" '[ $bad -eq 0 ]'

# 4. A sequence interrupted by SIGINT (Ctrl-C) and by SIGTERM resumes where it stopped.
seq="$work/seq"
mkdir -p "$seq/in" "$seq/out"
for f in $(seq 1 16); do ln -s "$work/in.exr" "$seq/in/s.$(printf %04d "$f").exr"; done
for sig in INT TERM; do
  rm -f "$seq/out"/* "$seq/out"/.[!.]* 2>/dev/null
  "$cgtmo" apply "$seq/in/s.####.exr" -o "$seq/out/s.####.png" --op agx --threads 1 -q & pid=$!
  sleep "$(awk "BEGIN{print $run_ms * 3 / 1000}")"
  kill -s "$sig" "$pid"; wait "$pid"; rc=$?
  n_done=$(ls "$seq/out" | wc -l)
  check "SIG$sig: exit 130" '[ $rc -eq 130 ]'
  check "SIG$sig: stopped early ($n_done of 16 written), no temporaries" '[ "$n_done" -lt 16 ] && ! ls -A "$seq/out" | grep -q cgtmo-tmp'
  out=$("$cgtmo" apply "$seq/in/s.####.exr" -o "$seq/out/s.####.png" --op agx 2>&1 >/dev/null | tail -1)
  check "SIG$sig: rerun skips the $n_done done frames" 'echo "$out" | grep -q "$((16 - n_done)) done, $n_done skipped, 0 failed"'
done

# 5. SIGKILL between the temporary's link and its rename leaves a hidden temporary; the next run
#    writing that output removes it (its writer's lock died with it).
if command -v strace >/dev/null; then
  dir="$work/linked"
  mkdir -p "$dir"
  strace -f -o /dev/null -e trace=rename,renameat,renameat2 -e inject=rename,renameat,renameat2:error=EIO:signal=SIGKILL \
    "$cgtmo" apply "$work/in.exr" -o "$dir/out.png" --op agx -q 2>/dev/null
  check "killed before rename: a temporary is left" 'ls -A "$dir" | grep -q "^\.out\.cgtmo-tmp-.*\.png$"'
  err=$("$cgtmo" apply "$work/in.exr" -o "$dir/out.png" --op agx 2>&1 >/dev/null)
  check "killed before rename: the next run removes it, says so, and writes the output" \
    'only_files "$dir" out.png && echo "$err" | grep -q "removed 1 temporary file left by an interrupted run"'
else
  echo "skip killed before rename (no strace)"
fi

# 6. A scene bake killed while it runs. Its outputs (LUT + config copy) are staged, then renamed
#    one by one at the end, the config last, SIGTERM held back meanwhile: a SIGTERM leaves the
#    previous set or the new one, whole, and no staging folder; a SIGKILL before the commit the
#    previous set and a staging folder that the next bake removes; a SIGKILL inside the commit
#    (between two renames) the files renamed so far new and the config the previous one.
bake="$work/bake"
mkdir -p "$bake/luts" "$bake/cfg"
cp "$root/ocio_config/config.ocio" "$bake/cfg/"
bake_night=(bake --scene "$root/tests/scenes/night/night.exr" --name shot --out-luts "$bake/luts" --out-config "$bake/cfg")
set_sum() { (cd "$bake" && find . -type f ! -path '*/.cgtmo-staging-*' | sort | xargs md5sum) | md5sum; }
staging_left() { compgen -G "$bake/luts/.cgtmo-staging-*" >/dev/null || compgen -G "$bake/cfg/.cgtmo-staging-*" >/dev/null; }
# Starts cgtmo with the remaining arguments, to stop itself at the point $1 (CGTMO_TEST_PAUSE_AT);
# returns once it has (state T), its pid in $pid. It polls a state the process keeps until it is
# signalled, so no timing decides what a kill interrupts; a run that ends first is a failure.
run_paused() {
  local point=$1 state; shift
  CGTMO_TEST_PAUSE_AT=$point "$cgtmo" "$@" >>"$work/paused.log" 2>&1 & pid=$!
  while state=$(sed 's/^.*) //' "/proc/$pid/stat" 2>/dev/null | cut -d' ' -f1); [ -n "$state" ] && [ "$state" != T ] && [ "$state" != Z ]; do
    sleep 0.01
  done
  [ "$state" = T ] || { echo "  cgtmo $1 ended before reaching $point"; fail=1; }
}
# On a full disk (a 160 KB tmpfs holding the 94 KB base config; the copy needs 100 KB more):
# exit 1 (an I/O failure, not a usage error), one line naming the cause, nothing left.
full="$work/bakefull"
mkdir -p "$full" && mount -t tmpfs -o size=160k tmpfs "$full" && mkdir "$full/luts" "$full/cfg" && cp "$root/ocio_config/config.ocio" "$full/cfg/"
err=$("$cgtmo" bake --scene "$root/tests/scenes/cornell/cornell.exr" --name shot --out-luts "$full/luts" --out-config "$full/cfg" -q 2>&1); rc=$?
check "bake on a full disk: exit 1, one line naming the cause ($err)" '[ $rc -eq 1 ] && [ "$(echo "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "No space left on device"'
check "bake on a full disk: nothing left" '[ -z "$(ls -A "$full/luts")" ] && only_files "$full/cfg" config.ocio'
mount -o remount,ro "$full"
err=$("$cgtmo" bake --scene "$root/tests/scenes/cornell/cornell.exr" --name shot --out-luts "$full/luts" --out-config "$full/cfg" -q 2>&1); rc=$?
check "bake into a read-only folder: exit 1, naming it ($err)" '[ $rc -eq 1 ] && echo "$err" | grep -q "Read-only file system"'
umount "$full"
"$cgtmo" bake --scene "$root/tests/scenes/cornell/cornell.exr" --name shot --out-luts "$bake/luts" --out-config "$bake/cfg" -q
cp -a "$bake" "$work/bake.old"
# Every run of bake_night below is the same command (the command line is written into the
# outputs): not quiet, for the note on removed staging folders, its output discarded.
old_set=$(set_sum) old_config=$(md5sum < "$bake/cfg/shot.ocio")
"$cgtmo" "${bake_night[@]}" >/dev/null 2>&1
new_set=$(set_sum) new_lut=$(cd "$bake/luts" && ls drago-shot.* | head -1)
new_lut_sum=$(md5sum < "$bake/luts/$new_lut")
restore_old() { rm -rf "$bake" && cp -a "$work/bake.old" "$bake"; }
# Each kill lands at a named point (the bake stops itself there: CGTMO_TEST_PAUSE_AT,
# src/cgtmo/util/test_pause.h), so the state it interrupts is known, however loaded the machine:
#   staging-folder-made  a staging folder made, not yet registered for the handler's clean-up;
#   commit-start         every file staged, none renamed;
#   commit-renamed       the first file (the LUT) renamed, the config (renamed last) not yet.
for point in staging-folder-made commit-start; do
  restore_old
  run_paused "$point" "${bake_night[@]}"; kill -9 "$pid"; wait "$pid" 2>/dev/null
  check "bake SIGKILLed at $point: the previous set, whole, its staging folder left" '[ "$(set_sum)" = "$old_set" ] && staging_left'
  err=$("$cgtmo" "${bake_night[@]}" 2>&1 >/dev/null)  # not quiet: the removal is reported
  check "  the next bake removes it, says so, and leaves the new set and no staging folder" \
    '! staging_left && [ "$(set_sum)" = "$new_set" ] && echo "$err" | grep -q "removed 1 staging folder left by an interrupted run"'
done
# Inside the commit a SIGKILL leaves what docs/hardening.md says: the files renamed so far new,
# the config (renamed last) the previous one, the others in the staging folder.
restore_old
run_paused commit-renamed "${bake_night[@]}"; kill -9 "$pid"; wait "$pid" 2>/dev/null
check "bake SIGKILLed between two renames: the LUT new, the config the previous one, the staging folder left" \
  '[ "$(md5sum < "$bake/luts/$new_lut")" = "$new_lut_sum" ] && [ "$(md5sum < "$bake/cfg/shot.ocio")" = "$old_config" ] && staging_left'
"$cgtmo" "${bake_night[@]}" >/dev/null 2>&1
check "  the next bake completes the new set" '! staging_left && [ "$(set_sum)" = "$new_set" ]'
# SIGTERM (delivered by SIGCONT): before the commit the handler removes the staging folder (one
# made but not yet registered included: the signal waits for its registration); inside the
# commit it waits for the renames to end.
# At commit-start the SIGTERM may be handled by a worker thread while the stopped thread goes on
# into the commit, which then defers it and finishes: either whole set is right there (it failed
# once under load when the test wanted the previous one only).
for point in staging-folder-made commit-start commit-renamed; do
  want=$old_set also=$old_set what=previous
  [ "$point" = commit-start ] && also=$new_set what="previous or the new"
  [ "$point" = commit-renamed ] && want=$new_set also=$new_set what=new
  restore_old
  run_paused "$point" "${bake_night[@]}"; kill -TERM "$pid"; kill -CONT "$pid"; wait "$pid"; rc=$?
  check "bake SIGTERMed at $point: exit 143 ($rc), no staging folder, the $what set whole" \
    '[ $rc -eq 143 ] && ! staging_left && { [ "$(set_sum)" = "$want" ] || [ "$(set_sum)" = "$also" ]; }'
done
for point in commit-start commit-renamed; do
  rm -rf "$bake/luts"/* "$bake/cfg/shot.ocio"  # a fresh folder: no previous set
  run_paused "$point" "${bake_night[@]}"; kill -TERM "$pid"; kill -CONT "$pid"; wait "$pid"; rc=$?
  check "bake SIGTERMed at $point into a fresh folder: exit 143 ($rc), no staging folder, nothing or the whole set" \
    '[ $rc -eq 143 ] && ! staging_left && { { [ -z "$(ls -A "$bake/luts")" ] && [ ! -e "$bake/cfg/shot.ocio" ]; } || [ "$(set_sum)" = "$new_set" ]; }'
done

# 7. bake --into: config.ocio names one set folder (cgtmo-set-<hash>), placed whole before
#    config.ocio is replaced by one rename. Killed at each point of the commit, the output folder
#    holds the previous config and its set, or the new config and its set, whole; the next merge
#    removes what the killed one left (its staging folder, a set that no config names).
into="$work/into"
mkdir -p "$into/studio/luts"
cat > "$into/studio/studio.ocio" <<'EOF'
ocio_profile_version: 2
search_path: "luts:luts"
roles:
  scene_linear: Linear
  default: Linear
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: Linear
  - !<ColorSpace>
    name: sRGB
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Film
    to_scene_reference: !<FileTransform> {src: film.spi1d, interpolation: linear}
EOF
printf 'Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0\n1\n}\n' > "$into/studio/luts/film.spi1d"
merge=(bake --into "$into/studio/studio.ocio" -o "$into/out" --cgtmo-config "$root/ocio_config/config.ocio" -q)
named_set() { grep -o 'cgtmo-set-[0-9a-f-]*' "$into/out/config.ocio" | head -1; }
merge_state() {  # config.ocio and the files of the set it names, as one checksum
  local set; set=$(named_set)
  { md5sum < "$into/out/config.ocio"; [ -n "$set" ] && (cd "$into/out/$set" && find . -type f | sort | xargs md5sum); } | md5sum
}
into_staging_left() { compgen -G "$into/out/.cgtmo-staging-*" >/dev/null; }
"$cgtmo" "${merge[@]}"
cp -a "$into/out" "$into/out.old"
old_merge=$(merge_state)
printf 'Version 1\nFrom 0.0 1.0\nLength 3\nComponents 1\n{\n0\n0.5\n1\n}\n' > "$into/studio/luts/film.spi1d"
"$cgtmo" "${merge[@]}"
new_merge=$(merge_state) new_set_name=$(named_set)
check "merge: a new set replaces the previous one: config.ocio and one set, nothing else" \
  '[ "$new_merge" != "$old_merge" ] && only_files "$into/out" config.ocio "$new_set_name"'
restore_merge() { rm -rf "$into/out" && cp -a "$into/out.old" "$into/out"; }
for point in staging-folder-made merge-commit-start merge-set-placed merge-config-renamed; do
  want=$old_merge what=previous
  [ "$point" = merge-config-renamed ] && want=$new_merge what=new
  restore_merge
  run_paused "$point" "${merge[@]}"; kill -9 "$pid"; wait "$pid" 2>/dev/null
  check "merge SIGKILLed at $point: the $what config and its set, whole" '[ "$(merge_state)" = "$want" ]'
  "$cgtmo" "${merge[@]}"
  check "  the next merge leaves the new config and its set, nothing else" \
    '[ "$(merge_state)" = "$new_merge" ] && only_files "$into/out" config.ocio "$new_set_name"'
  # SIGTERM: before the commit nothing changes; inside it, the commit ends first. At the commit's
  # start a worker thread may take the signal while the stopped thread enters the commit (see the
  # bake above): either whole state is right there.
  want=$old_merge also=$old_merge what=previous
  case $point in merge-set-placed|merge-config-renamed) want=$new_merge also=$new_merge what=new ;; esac
  [ "$point" = merge-commit-start ] && also=$new_merge what="previous or the new"
  restore_merge
  run_paused "$point" "${merge[@]}"; kill -TERM "$pid"; kill -CONT "$pid"; wait "$pid"; rc=$?
  check "merge SIGTERMed at $point: exit 143 ($rc), no staging folder, the $what config and its set" \
    '[ $rc -eq 143 ] && ! into_staging_left && { { [ "$(merge_state)" = "$old_merge" ] && [ "$want" = "$old_merge" -o "$also" = "$old_merge" ]; } || { [ "$(merge_state)" = "$new_merge" ] && [ "$want" = "$new_merge" -o "$also" = "$new_merge" ] && only_files "$into/out" config.ocio "$new_set_name"; }; }'
done

# 8. pid namespaces: cgtmo runs as pid 1 in each, so pids collide and say nothing about liveness.
if unshare -p -f --mount-proc true 2>/dev/null; then
  ns="$work/ns"
  mkdir -p "$ns/in" "$ns/out"
  # The shot: 24 small frames.
  /usr/bin/python3 - "$ns/in" <<'PY'
import sys, numpy as np, OpenImageIO as oiio
for f in range(1, 25):
    img = np.exp2(np.random.default_rng(f).uniform(-8, 10, (72, 128, 3))).astype(np.float32)
    p = f"{sys.argv[1]}/s.{f:04d}.exr"
    out = oiio.ImageOutput.create(p); out.open(p, oiio.ImageSpec(128, 72, 3, oiio.HALF)); out.write_image(img); out.close()
PY
  # a) A writer in one namespace holds its temporary (locked, as cgtmo holds it) while a run in
  #    another namespace writes the same frame: the live temporary stays. Once the writer has
  #    ended, the next run removes it. A temporary named by a pid alone (its pid is alive here,
  #    but not in the run's namespace) is not judged by that pid: it stays until 24 h old.
  boot=$(tr -d '-' < /proc/sys/kernel/random/boot_id | cut -c1-8)
  live="$ns/out/.s.0001.cgtmo-tmp-$boot-1-0badc0de.png" by_pid="$ns/out/.s.0001.cgtmo-tmp-$$.png"
  : > "$live"; : > "$by_pid"
  unshare -p -f --kill-child flock "$live" sleep 60 & holder=$!
  for _ in $(seq 500); do flock -n "$live" true || break; sleep 0.01; done  # until the holder has its lock
  unshare -p -f --mount-proc "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --frames 1 --force --op agx -q
  check "pid namespaces: a live writer's temporary survives a run in another namespace" '[ -e "$live" ] && [ -e "$by_pid" ] && [ -s "$ns/out/s.0001.png" ]'
  kill -9 "$holder"; wait "$holder" 2>/dev/null  # --kill-child ends the holder with it
  for _ in $(seq 500); do flock -n "$live" true && break; sleep 0.01; done  # until its lock is gone
  unshare -p -f --mount-proc "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --frames 1 --force --op agx -q
  check "pid namespaces: once its writer has ended, the next run removes it" 'only_files "$ns/out" s.0001.png "$(basename "$by_pid")"'
  rm -f "$by_pid"
  # b) The same with cgtmo's own writer: strace holds it 2 s at its rename, its temporary named,
  #    while a run in another namespace writes that frame. Both succeed; nothing is left.
  if command -v strace >/dev/null; then
    # LeakSanitizer cannot run under ptrace: a sanitizer build checks leaks in the other runs.
    ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" unshare -p -f --mount-proc strace -f -o /dev/null \
      -e trace=rename,renameat,renameat2 -e inject=rename,renameat,renameat2:delay_enter=2s \
      "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --frames 1 --force --op agx -q & writer=$!
    for _ in $(seq 1000); do compgen -G "$ns/out/.s.0001.cgtmo-tmp-*" >/dev/null && break; sleep 0.01; done
    held=$(ls -A "$ns/out" | grep -c cgtmo-tmp)
    unshare -p -f --mount-proc "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --frames 1 --force --op agx -q; rc2=$?
    still=$(ls -A "$ns/out" | grep -c cgtmo-tmp)
    wait "$writer"; rc1=$?
    check "pid namespaces: a writer held at its rename keeps its temporary ($held, then $still) and succeeds (exits $rc1, $rc2)" \
      '[ "$held" -eq 1 ] && [ "$still" -eq 1 ] && [ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] && only_files "$ns/out" s.0001.png'
  fi
  # c) Two sequences of one shot into one folder at once, each in its own namespace as pid 1.
  mkdir -p "$ns/ref"
  "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/ref/s.####.png" --op agx -q
  rcs=""
  for run in 1 2 3; do
    rm -f "$ns/out"/* "$ns/out"/.[!.]* 2>/dev/null
    unshare -p -f --mount-proc "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --op agx --force -q & a=$!
    unshare -p -f --mount-proc "$cgtmo" apply "$ns/in/s.####.exr" -o "$ns/out/s.####.png" --op agx --force -q & b=$!
    wait "$a"; ra=$?; wait "$b"; rb=$?
    rcs="$rcs $ra/$rb"
    lost=0
    for f in $(seq -f %04g 1 24); do cmp -s "$ns/out/s.$f.png" "$ns/ref/s.$f.png" || lost=$((lost + 1)); done
    [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ $lost -eq 0 ] && [ "$(ls -A "$ns/out" | wc -l)" -eq 24 ] || break
  done
  check "pid namespaces: two sequences into one folder at once, 3 times (exits$rcs): every frame complete, nothing else" \
    '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ $lost -eq 0 ] && [ "$(ls -A "$ns/out" | wc -l)" -eq 24 ]'
else
  echo "skip pid namespaces (unshare -p not permitted)"
fi

[ $fail -eq 0 ] && echo "all fault tests passed"
exit $fail
