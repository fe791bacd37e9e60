#pragma once
// Running a program as a child for the bench programs: output discarded, its wall time and its own
// peak resident memory (wait4's rusage, not the parent's). Header-only: bench/ programs only.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

extern "C" char** environ;

namespace cgtmo::bench {

struct ChildRun {
  bool started = false;
  int exit_status = -1;  // -1 when it did not exit normally
  double ms = 0;         // from spawn to exit
  double peak_rss_mb = 0;
};

inline ChildRun run_child(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<std::string> all = {exe};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  ChildRun r;
  pid_t pid = -1;
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return r;
  int status = 0;
  rusage u{};
  if (wait4(pid, &status, 0, &u) != pid) return r;
  r.started = true;
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.peak_rss_mb = double(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace cgtmo::bench
