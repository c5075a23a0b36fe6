#pragma once
// The CPUs a rendering process may use: its affinity mask (which `mpirun --bind-to` or a
// scheduler's binding sets), and, inside a Slurm job, what Slurm allocated it. Without a
// binding (Slurm's task/none, mpirun's --bind-to none) the mask is the whole machine while the
// job holds only part of it; the allocation then decides:
//   SLURM_CPUS_PER_TASK (sbatch --cpus-per-task) is each process's share;
//   else SLURM_CPUS_ON_NODE (the job's CPUs on this node) is shared evenly among the
//   `sharingProcesses` that render on the node (at least one CPU each).
// Never more than the mask, and at least 1.

#include <functional>

namespace prt {

using EnvLookup = std::function<const char*(const char*)>;

int allocatedCpuCount(int sharingProcesses = 1);
int allocatedCpuCount(int sharingProcesses, int affinityCpus, const EnvLookup& env);

}  // namespace prt
