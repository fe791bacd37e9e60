#pragma once
// Named moments at which a test can find the process in a known state, instead of guessing one
// with sleeps. With CGTMO_TEST_PAUSE_AT=<name> in the environment, the process stops itself
// (SIGSTOP) the first time it reaches that point (a point inside a loop: after its first turn);
// the test waits until it is stopped (state T in /proc/<pid>/stat), then kills it (SIGKILL),
// signals it (SIGTERM, then SIGCONT to deliver it), or lets it go on (SIGCONT). Unset, a point
// costs one comparison.
namespace cgtmo {

void test_pause_point(const char* name);

}  // namespace cgtmo
