#pragma once
// What this process is allotted on the machine it runs on: CPUs and memory, in one place for the
// thread pool (util/parallel.h), the readers' memory budget (io/input_file.h) and how many frames
// of a sequence run at once. A farm node is shared: the machine's core count and RAM are rarely
// what a job may use.
//   CPUs:   the fewest of the affinity mask (taskset, cpusets), the cgroup CPU quota (v2 cpu.max,
//           v1 cpu.cfs_quota_us / cpu.cfs_period_us, rounded up) and SLURM_CPUS_PER_TASK.
//   Memory: the least of the physical RAM, the cgroup memory limit (v2 memory.max, v1
//           memory.limit_in_bytes), SLURM_MEM_PER_NODE and SLURM_MEM_PER_CPU x the CPUs.
// Every cgroup on this process's path (from /proc/self/cgroup) up to the root is read: the
// tightest limit on the path counts. An environment value that is not a positive number that fits
// (e.g. "abc", "-5", "99999999999999999999") is ignored; SLURM_MEM_PER_NODE=0 means all the node's
// memory and is ignored too.
#include <cstdint>
#include <functional>
#include <string>

namespace cgtmo {

struct Allocation {
  int cpus = 1;
  std::string cpus_source;  // what set `cpus`: "affinity mask", "cgroup cpu.max", "SLURM_CPUS_PER_TASK", ...
  std::uint64_t memory_bytes = 0;
  std::string memory_source;  // "RAM", "cgroup memory.max", "SLURM_MEM_PER_NODE", "SLURM_MEM_PER_CPU", ...
};

// What compute_allocation reads, passed in explicitly so that it can be tested.
struct AllocationInputs {
  int affinity_cpus = 0;        // CPUs in the affinity mask (0: unknown, counted as 1)
  std::uint64_t ram_bytes = 0;  // physical RAM (0: unknown, counted as 8 GiB)
  std::string cgroup_root = "/sys/fs/cgroup";
  std::string proc_self_cgroup;                   // the contents of /proc/self/cgroup
  std::function<const char*(const char*)> getenv;  // nullptr for none set; empty: no environment
};

// The CPUs and memory allotted, as described above. Never throws; unreadable files count as no limit.
Allocation compute_allocation(const AllocationInputs& in);

// The inputs of this process: sched_getaffinity (sized for any number of CPUs), sysconf's
// physical pages, /proc/self/cgroup, ::getenv.
AllocationInputs system_allocation_inputs();

// compute_allocation(system_allocation_inputs()), computed once.
const Allocation& process_allocation();

// The environment values, parsed strictly: a positive decimal integer that fits, else 0.
// Memory: megabytes by default, or with one suffix K, M, G or T (Slurm's units); returns bytes.
std::uint64_t parse_slurm_count(const char* text);
std::uint64_t parse_slurm_memory(const char* text);

}  // namespace cgtmo
