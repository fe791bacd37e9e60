// util/allocation: CPUs and memory from the affinity mask, a cgroup tree (made here in a temporary
// folder, v2 and v1 layouts), and Slurm's environment; garbage values are ignored.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "cgtmo/util/allocation.h"

namespace cgtmo {
namespace {

namespace fs = std::filesystem;
constexpr std::uint64_t kMiB = 1024 * 1024, kGiB = 1024 * kMiB;

// A fake /sys/fs/cgroup and environment, and the inputs that point at them.
class AllocationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root = fs::temp_directory_path() / ("cgtmo_allocation_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(root);
    fs::create_directories(root);
  }
  void TearDown() override { fs::remove_all(root); }

  void write(const std::string& rel, const std::string& text) {
    const fs::path p = root / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text << "\n";
  }

  AllocationInputs inputs(int affinity = 8, std::uint64_t ram = 64 * kGiB) {
    AllocationInputs in;
    in.affinity_cpus = affinity;
    in.ram_bytes = ram;
    in.cgroup_root = root.string();
    in.proc_self_cgroup = proc;
    in.getenv = [this](const char* name) -> const char* {
      const auto it = env.find(name);
      return it == env.end() ? nullptr : it->second.c_str();
    };
    return in;
  }

  fs::path root;
  std::string proc = "0::/\n";
  std::map<std::string, std::string> env;
};

TEST_F(AllocationTest, NothingSetIsTheAffinityMaskAndTheRam) {
  const Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 8);
  EXPECT_EQ(a.cpus_source, "affinity mask");
  EXPECT_EQ(a.memory_bytes, 64 * kGiB);
  EXPECT_EQ(a.memory_source, "RAM");
}

TEST_F(AllocationTest, AffinityMaskOfOne) {
  const Allocation a = compute_allocation(inputs(1));
  EXPECT_EQ(a.cpus, 1);
  EXPECT_EQ(a.cpus_source, "affinity mask");
}

TEST_F(AllocationTest, CgroupV2CpuMaxRoundsUp) {
  write("cpu.max", "50000 100000");
  Allocation a = compute_allocation(inputs(8));
  EXPECT_EQ(a.cpus, 1);
  EXPECT_EQ(a.cpus_source, "cgroup cpu.max");
  write("cpu.max", "150000 100000");
  a = compute_allocation(inputs(8));
  EXPECT_EQ(a.cpus, 2);
  EXPECT_EQ(a.cpus_source, "cgroup cpu.max");
  write("cpu.max", "max 100000");
  a = compute_allocation(inputs(8));
  EXPECT_EQ(a.cpus, 8);
  EXPECT_EQ(a.cpus_source, "affinity mask");
  // A quota above the affinity mask does not add CPUs.
  write("cpu.max", "1600000 100000");
  EXPECT_EQ(compute_allocation(inputs(4)).cpus, 4);
}

TEST_F(AllocationTest, NestedCgroupTightestLimitOnThePathWins) {
  proc = "0::/farm.slice/job_42/step_0\n";
  write("farm.slice/cpu.max", "200000 100000");
  write("farm.slice/job_42/cpu.max", "max 100000");
  write("farm.slice/job_42/step_0/cpu.max", "300000 100000");
  write("farm.slice/memory.max", std::to_string(16 * kGiB));
  write("farm.slice/job_42/memory.max", std::to_string(4 * kGiB));
  write("farm.slice/job_42/step_0/memory.max", "max");
  // A sibling that is not on this process's path counts for nothing.
  write("other.slice/cpu.max", "10000 100000");
  write("other.slice/memory.max", "1024");
  const Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 2);
  EXPECT_EQ(a.cpus_source, "cgroup cpu.max");
  EXPECT_EQ(a.memory_bytes, 4 * kGiB);
  EXPECT_EQ(a.memory_source, "cgroup memory.max");
}

TEST_F(AllocationTest, CgroupPathMissingFallsBackToTheRoot) {
  // Inside a container the cgroup filesystem's root is the container's own cgroup while
  // /proc/self/cgroup may still name the host's path.
  proc = "0::/docker/abcdef\n";
  write("cpu.max", "100000 100000");
  write("memory.max", std::to_string(3 * kGiB));
  const Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 1);
  EXPECT_EQ(a.memory_bytes, 3 * kGiB);
}

TEST_F(AllocationTest, CgroupV2MemoryMax) {
  write("memory.max", std::to_string(6 * kGiB));
  Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 6 * kGiB);
  EXPECT_EQ(a.memory_source, "cgroup memory.max");
  // A limit above the RAM leaves the RAM.
  write("memory.max", std::to_string(128 * kGiB));
  a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 64 * kGiB);
  EXPECT_EQ(a.memory_source, "RAM");
  write("memory.max", "max");
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_source, "RAM");
}

TEST_F(AllocationTest, CgroupV1QuotaAndMemoryLimit) {
  proc = "12:memory:/user/job\n4:cpu,cpuacct:/user/job\n1:name=systemd:/user/job\n";
  write("cpu,cpuacct/cpu.cfs_quota_us", "-1");
  write("cpu,cpuacct/cpu.cfs_period_us", "100000");
  write("cpu,cpuacct/user/job/cpu.cfs_quota_us", "250000");
  write("cpu,cpuacct/user/job/cpu.cfs_period_us", "100000");
  write("memory/memory.limit_in_bytes", "9223372036854771712");  // v1's "no limit"
  write("memory/user/memory.limit_in_bytes", std::to_string(5 * kGiB));
  write("memory/user/job/memory.limit_in_bytes", "9223372036854771712");
  const Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 3);
  EXPECT_EQ(a.cpus_source, "cgroup cpu.cfs_quota_us");
  EXPECT_EQ(a.memory_bytes, 5 * kGiB);
  EXPECT_EQ(a.memory_source, "cgroup memory.limit_in_bytes");
}

TEST_F(AllocationTest, CgroupV1NoQuota) {
  proc = "4:cpu,cpuacct:/\n";
  write("cpu,cpuacct/cpu.cfs_quota_us", "-1");
  write("cpu,cpuacct/cpu.cfs_period_us", "100000");
  write("memory/memory.limit_in_bytes", "9223372036854771712");
  const Allocation a = compute_allocation(inputs(6, 32 * kGiB));
  EXPECT_EQ(a.cpus, 6);
  EXPECT_EQ(a.cpus_source, "affinity mask");
  EXPECT_EQ(a.memory_bytes, 32 * kGiB);
  EXPECT_EQ(a.memory_source, "RAM");
}

TEST_F(AllocationTest, SlurmCpusPerTask) {
  env["SLURM_CPUS_PER_TASK"] = "1";
  const Allocation a = compute_allocation(inputs(8));
  EXPECT_EQ(a.cpus, 1);
  EXPECT_EQ(a.cpus_source, "SLURM_CPUS_PER_TASK");
  // More than the affinity mask allows does not add CPUs.
  env["SLURM_CPUS_PER_TASK"] = "16";
  EXPECT_EQ(compute_allocation(inputs(8)).cpus, 8);
}

TEST_F(AllocationTest, SlurmMemPerNode) {
  env["SLURM_MEM_PER_NODE"] = "2048";
  Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 2 * kGiB);
  EXPECT_EQ(a.memory_source, "SLURM_MEM_PER_NODE");
  env["SLURM_MEM_PER_NODE"] = "4G";
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_bytes, 4 * kGiB);
  env["SLURM_MEM_PER_NODE"] = "512M";
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_bytes, 512 * kMiB);
  env["SLURM_MEM_PER_NODE"] = "1048576K";
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_bytes, 1 * kGiB);
  env["SLURM_MEM_PER_NODE"] = "1T";
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_source, "RAM");
  // 0: all the node's memory.
  env["SLURM_MEM_PER_NODE"] = "0";
  a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 64 * kGiB);
  EXPECT_EQ(a.memory_source, "RAM");
}

TEST_F(AllocationTest, SlurmMemPerCpuTimesTheCpus) {
  env["SLURM_MEM_PER_CPU"] = "1000";
  // Without SLURM_CPUS_PER_TASK: the CPUs computed (a 2-CPU affinity mask).
  Allocation a = compute_allocation(inputs(2, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 2000 * kMiB);
  EXPECT_EQ(a.memory_source, "SLURM_MEM_PER_CPU");
  // With it: the CPUs per task.
  env["SLURM_CPUS_PER_TASK"] = "2";
  a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 2);
  EXPECT_EQ(a.memory_bytes, 2000 * kMiB);
  // A cgroup limit below it wins.
  write("memory.max", std::to_string(1000 * kMiB));
  a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.memory_bytes, 1000 * kMiB);
  EXPECT_EQ(a.memory_source, "cgroup memory.max");
}

TEST_F(AllocationTest, GarbageEnvironmentIsIgnored) {
  for (const char* bad : {"abc", "-5", "99999999999999999999", "", " 4", "4 ", "2.5", "0x10", "4GB", "G", "1e3",
                          "99999999999999999999999999999999"}) {
    env["SLURM_CPUS_PER_TASK"] = bad;
    env["SLURM_MEM_PER_NODE"] = bad;
    env["SLURM_MEM_PER_CPU"] = bad;
    const Allocation a = compute_allocation(inputs(8, 64 * kGiB));
    EXPECT_EQ(a.cpus, 8) << "'" << bad << "'";
    EXPECT_EQ(a.cpus_source, "affinity mask") << "'" << bad << "'";
    EXPECT_EQ(a.memory_bytes, 64 * kGiB) << "'" << bad << "'";
    EXPECT_EQ(a.memory_source, "RAM") << "'" << bad << "'";
  }
  // A number of megabytes whose bytes overflow 64 bits, and a per-CPU figure that overflows
  // when multiplied by the CPUs.
  env.clear();
  env["SLURM_MEM_PER_NODE"] = "17592186044416";  // 2^44 MB = 2^64 bytes
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_source, "RAM");
  env.clear();
  env["SLURM_MEM_PER_CPU"] = "4398046511104";  // 2^42 MB x 8 CPUs = 2^65 bytes
  EXPECT_EQ(compute_allocation(inputs(8, 64 * kGiB)).memory_source, "RAM");
  env.clear();
  env["SLURM_CPUS_PER_TASK"] = "0";
  EXPECT_EQ(compute_allocation(inputs(8)).cpus, 8);
}

TEST_F(AllocationTest, GarbageCgroupFilesAreIgnored) {
  proc = "garbage\n0::/../../etc\n";
  write("cpu.max", "lots 100000");
  write("memory.max", "-1");
  Allocation a = compute_allocation(inputs(8, 64 * kGiB));
  EXPECT_EQ(a.cpus, 8);
  EXPECT_EQ(a.memory_source, "RAM");
  write("cpu.max", "100000 0");
  EXPECT_EQ(compute_allocation(inputs(8)).cpus, 8);
  write("cpu.max", "0 100000");
  EXPECT_EQ(compute_allocation(inputs(8)).cpus, 8);
}

TEST_F(AllocationTest, NoEnvironmentAndUnknownFigures) {
  AllocationInputs in;
  in.cgroup_root = (root / "absent").string();
  const Allocation a = compute_allocation(in);
  EXPECT_EQ(a.cpus, 1);
  EXPECT_GT(a.memory_bytes, 0u);
}

TEST(ProcessAllocation, IsAtLeastOneCpuAndSomeMemory) {
  const Allocation& a = process_allocation();
  EXPECT_GE(a.cpus, 1);
  EXPECT_FALSE(a.cpus_source.empty());
  EXPECT_GT(a.memory_bytes, 0u);
  EXPECT_FALSE(a.memory_source.empty());
  EXPECT_GE(system_allocation_inputs().affinity_cpus, a.cpus);
}

}  // namespace
}  // namespace cgtmo
