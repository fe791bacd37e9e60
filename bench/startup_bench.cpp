// cgtmo-startup-bench: what starting the shipped tool costs. Runs `cgtmo --version` and the
// minimal OpenImageIO + OpenColorIO program (minimal_oiio_ocio.cpp) alternately, N times each, and
// prints for each the median wall time from spawn to exit, the median peak resident memory (the
// child's own, from wait4) and the shared libraries it loads (ldd), then the ratios cgtmo/minimal.
// Alternating the two keeps a shared machine's load from favouring either.
//
// Usage: cgtmo-startup-bench [RUNS] [CGTMO] [MINIMAL]   (defaults: 31, the programs built here)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.h"

namespace {

struct Sample {
  double ms = 0, rss_mb = 0;
};

// One run of `exe args...`, output discarded; false when it cannot start or fails.
bool run_once(const std::string& exe, const std::vector<std::string>& args, Sample& s) {
  const cgtmo::bench::ChildRun r = cgtmo::bench::run_child(exe, args);
  s.ms = r.ms;
  s.rss_mb = r.peak_rss_mb;
  return r.started && r.exit_status == 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The shared libraries the dynamic loader maps for `exe` (lines of ldd naming a library), or -1.
int shared_libraries(const std::string& exe) {
  const std::string cmd = "ldd '" + exe + "' 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  int n = 0;
  char line[4096];
  while (std::fgets(line, sizeof line, p))
    if (std::string(line).find(".so") != std::string::npos) ++n;
  return pclose(p) == 0 ? n : -1;
}

std::string first_line(const std::string& path, const std::string& prefix) {
  std::ifstream f(path);
  std::string line;
  while (std::getline(f, line))
    if (prefix.empty() || line.rfind(prefix, 0) == 0) return prefix.empty() ? line : line.substr(line.find(':') + 2);
  return "unknown";
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 31;
  std::string cgtmo = CGTMO_CLI_PATH, minimal = CGTMO_MINIMAL_PATH;
  if (argc > 1 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::cout << "usage: cgtmo-startup-bench [RUNS] [CGTMO] [MINIMAL]\n";
    return 0;
  }
  if (argc > 1) {
    char* end = nullptr;
    const long n = std::strtol(argv[1], &end, 10);
    if (*end != '\0' || n < 1 || n > 10000) {
      std::cerr << "cgtmo-startup-bench: error: RUNS '" << argv[1] << "' is not a count in [1, 10000]\n";
      return 2;
    }
    runs = int(n);
  }
  if (argc > 2) cgtmo = argv[2];
  if (argc > 3) minimal = argv[3];
  if (argc > 4) {
    std::cerr << "cgtmo-startup-bench: error: too many arguments (usage: cgtmo-startup-bench [RUNS] [CGTMO] [MINIMAL])\n";
    return 2;
  }
  for (const std::string& exe : {cgtmo, minimal})
    if (access(exe.c_str(), X_OK) != 0) {
      std::cerr << "cgtmo-startup-bench: error: '" << exe << "' is not an executable\n";
      return 2;
    }

  std::vector<double> c_ms, c_rss, m_ms, m_rss;
  Sample s;
  // One untimed run each: the first start pays for reading the libraries from disk.
  if (!run_once(cgtmo, {"--version"}, s) || !run_once(minimal, {}, s)) {
    std::cerr << "cgtmo-startup-bench: error: a program failed to run\n";
    return 1;
  }
  for (int i = 0; i < runs; ++i) {
    if (!run_once(cgtmo, {"--version"}, s)) return 1;
    c_ms.push_back(s.ms), c_rss.push_back(s.rss_mb);
    if (!run_once(minimal, {}, s)) return 1;
    m_ms.push_back(s.ms), m_rss.push_back(s.rss_mb);
  }
  const double cm = median(c_ms), mm = median(m_ms), cr = median(c_rss), mr = median(m_rss);
  const int cl = shared_libraries(cgtmo), ml = shared_libraries(minimal);
  std::printf("machine: %s, %u logical CPUs, load average %s\n", first_line("/proc/cpuinfo", "model name").c_str(),
              std::thread::hardware_concurrency(), first_line("/proc/loadavg", "").c_str());
  std::printf("%d alternating runs each, medians\n", runs);
  std::printf("%-28s %10s %14s %16s\n", "program", "ms", "peak RSS MB", "shared libs");
  std::printf("%-28s %10.2f %14.1f %16d\n", "cgtmo --version", cm, cr, cl);
  std::printf("%-28s %10.2f %14.1f %16d\n", "minimal OIIO+OCIO program", mm, mr, ml);
  std::printf("%-28s %10.2fx %13.2fx %15.2fx\n", "ratio cgtmo / minimal", cm / mm, cr / mr, ml > 0 ? double(cl) / ml : 0.0);
  return 0;
}
