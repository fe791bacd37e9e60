#include "cgtmo/util/allocation.h"

#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

namespace cgtmo {

namespace {

constexpr std::uint64_t kMaxCpus = 1u << 22;  // more is not a CPU count but garbage
constexpr std::uint64_t kUnknownRam = std::uint64_t(8) << 30;

// The first line of a file, or "" when it cannot be read.
std::string first_line(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (in) std::getline(in, line);
  return line;
}

// A whole token of decimal digits that fits in 64 bits, else false.
bool parse_u64(const std::string& s, std::uint64_t* out) {
  if (s.empty() || s.size() > 20) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if (errno == ERANGE) return false;
  *out = v;
  return true;
}

// The folders from `base` + `path` up to `base`, deepest first. A path with ".." yields `base` alone.
std::vector<std::string> cgroup_folders(const std::string& base, const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '/');) {
    if (p.empty() || p == ".") continue;
    if (p == "..") return {base};
    parts.push_back(p);
  }
  std::vector<std::string> out;
  for (std::size_t n = parts.size() + 1; n-- > 0;) {
    std::string dir = base;
    for (std::size_t i = 0; i < n; ++i) dir += "/" + parts[i];
    out.push_back(dir);
  }
  return out;
}

// This process's cgroup paths from /proc/self/cgroup: the v2 one ("0::/path") and, for cgroup v1,
// the one of the hierarchy holding `controller` ("4:cpu,cpuacct:/path").
struct CgroupPaths {
  std::string v2 = "/", cpu_v1 = "/", memory_v1 = "/";
};

CgroupPaths parse_proc_self_cgroup(const std::string& text) {
  CgroupPaths p;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) {
    const auto a = line.find(':');
    const auto b = a == std::string::npos ? a : line.find(':', a + 1);
    if (b == std::string::npos) continue;
    const std::string id = line.substr(0, a), controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    if (id == "0" && controllers.empty()) {
      p.v2 = path;
      continue;
    }
    std::stringstream cs(controllers);
    for (std::string c; std::getline(cs, c, ',');) {
      if (c == "cpu") p.cpu_v1 = path;
      if (c == "memory") p.memory_v1 = path;
    }
  }
  return p;
}

// Keeps the smaller of the current figure and a candidate, with what set it; ties keep the first.
template <typename T>
void take_min(T* value, std::string* source, T candidate, const char* what) {
  if (candidate < *value) {
    *value = candidate;
    *source = what;
  }
}

// CPUs from a quota: ceil(quota / period), at least 1; 0 when there is no quota.
std::uint64_t quota_cpus(std::uint64_t quota, std::uint64_t period) {
  if (quota == 0 || period == 0) return 0;
  const std::uint64_t n = quota / period + (quota % period ? 1 : 0);
  return n < 1 ? 1 : n;
}

// cgroup v2 "cpu.max": "QUOTA PERIOD" or "max PERIOD"; 0 when there is no quota.
std::uint64_t cpu_max_cpus(const std::string& line) {
  std::stringstream ss(line);
  std::string quota, period;
  ss >> quota >> period;
  std::uint64_t q = 0, p = 100000;
  if (!parse_u64(quota, &q)) return 0;  // "max" or unreadable
  if (!period.empty() && !parse_u64(period, &p)) return 0;
  return quota_cpus(q, p);
}

// A folder of the v1 hierarchy holding `names` (e.g. "cpu,cpuacct"), or "" when none exists.
std::string v1_mount(const std::string& root, std::initializer_list<const char*> names) {
  for (const char* n : names) {
    const std::string dir = root + "/" + n;
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) return dir;
  }
  return "";
}

}  // namespace

std::uint64_t parse_slurm_count(const char* text) {
  std::uint64_t v = 0;
  if (!text || !parse_u64(text, &v) || v > kMaxCpus) return 0;
  return v;
}

std::uint64_t parse_slurm_memory(const char* text) {
  if (!text) return 0;
  std::string s = text;
  int shift = 20;  // megabytes unless a suffix says otherwise
  if (!s.empty()) {
    switch (s.back()) {
      case 'K': case 'k': shift = 10; s.pop_back(); break;
      case 'M': case 'm': shift = 20; s.pop_back(); break;
      case 'G': case 'g': shift = 30; s.pop_back(); break;
      case 'T': case 't': shift = 40; s.pop_back(); break;
      default: break;
    }
  }
  std::uint64_t v = 0;
  if (!parse_u64(s, &v) || v > (UINT64_MAX >> shift)) return 0;
  return v << shift;
}

Allocation compute_allocation(const AllocationInputs& in) {
  Allocation a;
  std::uint64_t cpus = in.affinity_cpus > 0 ? std::uint64_t(in.affinity_cpus) : 1;
  a.cpus_source = "affinity mask";
  a.memory_bytes = in.ram_bytes > 0 ? in.ram_bytes : kUnknownRam;
  a.memory_source = "RAM";

  const CgroupPaths paths = parse_proc_self_cgroup(in.proc_self_cgroup);
  // cgroup v2: every folder from this process's cgroup up to the root.
  for (const std::string& dir : cgroup_folders(in.cgroup_root, paths.v2)) {
    if (const std::uint64_t n = cpu_max_cpus(first_line(dir + "/cpu.max"))) take_min(&cpus, &a.cpus_source, n, "cgroup cpu.max");
    std::uint64_t m = 0;
    if (parse_u64(first_line(dir + "/memory.max"), &m) && m > 0)
      take_min(&a.memory_bytes, &a.memory_source, m, "cgroup memory.max");
  }
  // cgroup v1: the cpu and memory hierarchies, each from this process's cgroup up to its root.
  const std::string cpu_mount = v1_mount(in.cgroup_root, {"cpu,cpuacct", "cpu", "cpuacct,cpu"});
  if (!cpu_mount.empty())
    for (const std::string& dir : cgroup_folders(cpu_mount, paths.cpu_v1)) {
      const std::string quota = first_line(dir + "/cpu.cfs_quota_us");  // "-1": none
      std::uint64_t q = 0, p = 100000;
      if (!parse_u64(quota, &q)) continue;
      const std::string period = first_line(dir + "/cpu.cfs_period_us");
      if (!period.empty() && !parse_u64(period, &p)) continue;
      if (const std::uint64_t n = quota_cpus(q, p)) take_min(&cpus, &a.cpus_source, n, "cgroup cpu.cfs_quota_us");
    }
  const std::string memory_mount = v1_mount(in.cgroup_root, {"memory"});
  if (!memory_mount.empty())
    for (const std::string& dir : cgroup_folders(memory_mount, paths.memory_v1)) {
      std::uint64_t m = 0;  // no limit reads as about 2^63
      if (parse_u64(first_line(dir + "/memory.limit_in_bytes"), &m) && m > 0)
        take_min(&a.memory_bytes, &a.memory_source, m, "cgroup memory.limit_in_bytes");
    }

  // Slurm: what the job asked for (its cgroup usually says the same, when Slurm confines it).
  auto env = [&](const char* name) -> const char* { return in.getenv ? in.getenv(name) : nullptr; };
  const std::uint64_t slurm_cpus = parse_slurm_count(env("SLURM_CPUS_PER_TASK"));
  if (slurm_cpus) take_min(&cpus, &a.cpus_source, slurm_cpus, "SLURM_CPUS_PER_TASK");
  a.cpus = int(cpus);
  if (const std::uint64_t m = parse_slurm_memory(env("SLURM_MEM_PER_NODE")))
    take_min(&a.memory_bytes, &a.memory_source, m, "SLURM_MEM_PER_NODE");
  if (const std::uint64_t per_cpu = parse_slurm_memory(env("SLURM_MEM_PER_CPU"))) {
    const std::uint64_t n = slurm_cpus ? slurm_cpus : cpus;
    if (per_cpu <= UINT64_MAX / n) take_min(&a.memory_bytes, &a.memory_source, per_cpu * n, "SLURM_MEM_PER_CPU");
  }
  return a;
}

AllocationInputs system_allocation_inputs() {
  AllocationInputs in;
  // The affinity mask, in a set large enough for the machine (glibc's cpu_set_t holds 1024 CPUs;
  // sched_getaffinity fails with EINVAL when the kernel's mask is larger).
  for (int n = 1024; n <= (1 << 22) && in.affinity_cpus == 0; n *= 2) {
    cpu_set_t* set = CPU_ALLOC(n);
    if (!set) break;
    const std::size_t size = CPU_ALLOC_SIZE(n);
    CPU_ZERO_S(size, set);
    const bool ok = ::sched_getaffinity(0, size, set) == 0;
    const int err = errno;
    if (ok) in.affinity_cpus = CPU_COUNT_S(size, set);
    CPU_FREE(set);
    if (!ok && err != EINVAL) break;
  }
  if (in.affinity_cpus <= 0) in.affinity_cpus = int(std::thread::hardware_concurrency());
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page > 0) in.ram_bytes = std::uint64_t(pages) * std::uint64_t(page);
  std::ifstream f("/proc/self/cgroup");
  std::stringstream ss;
  ss << f.rdbuf();
  in.proc_self_cgroup = ss.str();
  in.getenv = [](const char* name) -> const char* { return std::getenv(name); };
  return in;
}

const Allocation& process_allocation() {
  static const Allocation a = compute_allocation(system_allocation_inputs());
  return a;
}

}  // namespace cgtmo
