#include "cluster/run_plan.h"

#include <cmath>

#include "core/input_error.h"
#include "core/number_format.h"

namespace prt {

void validateRunPlan(const RunPlan& plan, int totalWorkers) {
  validateStrategy(plan.strategy, plan.strategyOptions);
  if (plan.batchPixels < 1) throw InputError("--batch must be at least 1");
  if (!(plan.workerTimeoutSeconds >= kMinLeaseSeconds) ||
      !(plan.workerTimeoutSeconds <= kMaxLeaseSeconds)) {
    throw InputError("--worker-timeout must be between " + formatNumber(kMinLeaseSeconds) +
                     " and " + formatNumber(kMaxLeaseSeconds) + " seconds (got " +
                     formatNumber(plan.workerTimeoutSeconds) + ")");
  }
  validateJoinWaves(plan.joins, "--join-at");
  for (const FaultInjection& f : plan.faults) {
    if (f.worker < 0 || f.worker >= totalWorkers) {
      throw InputError("--inject-fault names worker " + std::to_string(f.worker) +
                       ", but the workers are numbered 0 to " + std::to_string(totalWorkers - 1) +
                       (plan.joins.empty() ? "" : " (with those that join)"));
    }
  }
}

}  // namespace prt
