# Sourced by the CLI's shell tests. `bounded CPU_SECONDS CMD...` runs CMD with its work bounded in
# CPU seconds (ulimit -t: the kernel stops it, exit 137 or 152), which the load of other
# processes does not stretch, so a bound can be tight and still hold on a busy farm node. The wall
# clock only catches a process that waits without working (a FIFO, a lock): its limit is wide, since
# on a loaded machine a few seconds of CPU can take minutes of wall time.
#   CGTMO_TEST_HANG_S: that wall-clock limit in seconds (default 120).
bounded() {
  local cpu=$1
  shift
  ( ulimit -t "$cpu" && exec timeout "${CGTMO_TEST_HANG_S:-120}" "$@" )
}
