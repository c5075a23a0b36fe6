#include "core/cpu_allocation.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace prt {
namespace {

EnvLookup fake(std::map<std::string, std::string> values) {
  return [values = std::move(values)](const char* name) -> const char* {
    const auto it = values.find(name);
    return it == values.end() ? nullptr : it->second.c_str();
  };
}

TEST(CpuAllocation, OutsideSlurmTheAffinityMaskDecides) {
  EXPECT_EQ(allocatedCpuCount(1, 8, fake({})), 8);
  EXPECT_EQ(allocatedCpuCount(3, 8, fake({})), 8);  // mpirun's binding already split it
  EXPECT_EQ(allocatedCpuCount(1, 0, fake({})), 1);
}

TEST(CpuAllocation, ASlurmJobUsesWhatItWasAllocatedOnTheNode) {
  // A 64-core machine, the job holding 16 of its cores, not bound (task/none).
  EXPECT_EQ(allocatedCpuCount(1, 64, fake({{"SLURM_CPUS_ON_NODE", "16"}})), 16);
  // Two rendering processes on the node share them.
  EXPECT_EQ(allocatedCpuCount(2, 64, fake({{"SLURM_CPUS_ON_NODE", "16"}})), 8);
  EXPECT_EQ(allocatedCpuCount(3, 64, fake({{"SLURM_CPUS_ON_NODE", "2"}})), 1);
  // Bound more tightly than the allocation: the mask.
  EXPECT_EQ(allocatedCpuCount(1, 4, fake({{"SLURM_CPUS_ON_NODE", "16"}})), 4);
}

TEST(CpuAllocation, CpusPerTaskIsEachProcesssShare) {
  EXPECT_EQ(allocatedCpuCount(4, 64, fake({{"SLURM_CPUS_ON_NODE", "32"},
                                           {"SLURM_CPUS_PER_TASK", "6"}})),
            6);
  EXPECT_EQ(allocatedCpuCount(1, 2, fake({{"SLURM_CPUS_PER_TASK", "6"}})), 2);
}

TEST(CpuAllocation, ValuesThatAreNotPositiveNumbersAreIgnored) {
  for (const char* bad : {"", "zero", "0", "-4", "99999999999"}) {
    EXPECT_EQ(allocatedCpuCount(1, 8, fake({{"SLURM_CPUS_ON_NODE", bad}})), 8) << bad;
    EXPECT_EQ(allocatedCpuCount(1, 8, fake({{"SLURM_CPUS_PER_TASK", bad}})), 8) << bad;
  }
}

}  // namespace
}  // namespace prt
