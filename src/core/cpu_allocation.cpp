#include "core/cpu_allocation.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/cpu_time.h"

namespace prt {
namespace {

// A whole positive number from the environment, or 0 when unset or not one.
int positive(const EnvLookup& env, const char* name) {
  const char* text = env(name);
  if (text == nullptr || *text == '\0') return 0;
  // SLURM_CPUS_ON_NODE is a plain number; a list such as "2(x3)" is not expected here, and
  // only its leading number would count.
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || value <= 0 || value > 1 << 20) return 0;
  return static_cast<int>(value);
}

}  // namespace

int allocatedCpuCount(int sharingProcesses, int affinityCpus, const EnvLookup& env) {
  int cpus = std::max(1, affinityCpus);
  if (const int perTask = positive(env, "SLURM_CPUS_PER_TASK")) {
    return std::min(cpus, perTask);
  }
  if (const int onNode = positive(env, "SLURM_CPUS_ON_NODE")) {
    cpus = std::min(cpus, std::max(1, onNode / std::max(1, sharingProcesses)));
  }
  return cpus;
}

int allocatedCpuCount(int sharingProcesses) {
  return allocatedCpuCount(sharingProcesses, affinityCpuCount(),
                           [](const char* name) { return std::getenv(name); });
}

}  // namespace prt
