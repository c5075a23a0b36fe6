// What a simulation may be asked: the plan's checks (cluster/run_plan.h) and those of what
// only a simulation has.
#include <cmath>
#include <string>

#include "core/input_error.h"
#include "sim/simulator.h"
#include "sim/worker_speeds.h"

namespace prt {

void validateSimulationOptions(const SimulationOptions& o, uint64_t pixelCount) {
  const auto workers = o.speeds.size();
  if (workers < 1) throw InputError("--workers must be at least 1");
  validateWorkerSpeeds(o.speeds, static_cast<int>(workers));
  validateRunPlan(o, static_cast<int>(workers));
  const int joiners = o.joinerCount();
  if (static_cast<size_t>(joiners) >= workers) {
    throw InputError("--join-at adds " + std::to_string(joiners) + " workers but the run has " +
                     std::to_string(workers) + " in all: at least one must start");
  }
  // The starting workers, as the thread driver counts them: joiners that find nothing left
  // simply get nothing.
  const size_t starting = workers - static_cast<size_t>(joiners);
  if (starting > pixelCount) {
    throw InputError("more workers (" + std::to_string(starting) + ") than pixels (" +
                     std::to_string(pixelCount) + ")");
  }
  if (!(o.batchSeconds >= 0 && o.batchSeconds <= 60)) {
    throw InputError("--batch-seconds must be in [0, 60] (0: batches of --batch pixels)");
  }
  if (!(o.batchOverheadSeconds >= 0) || !std::isfinite(o.batchOverheadSeconds)) {
    throw InputError("--batch-overhead-us must be finite and >= 0");
  }
  if (!(o.baseSpeedIndexSeconds > 0) || !std::isfinite(o.baseSpeedIndexSeconds)) {
    throw InputError("--speed-index must be a positive number of seconds");
  }
  if (!o.speedIndexSeconds.empty()) {
    if (o.speedIndexSeconds.size() != workers) {
      throw InputError("--speed-indices lists " + std::to_string(o.speedIndexSeconds.size()) +
                       " values for " + std::to_string(workers) + " workers; give one per worker");
    }
    for (double s : o.speedIndexSeconds) {
      if (!(s > 0) || !std::isfinite(s)) {
        throw InputError("--speed-indices values must be positive numbers of seconds");
      }
    }
  }
  for (const SpeedChange& c : o.speedChanges) {
    if (c.worker < 0 || static_cast<size_t>(c.worker) >= workers || !(c.value > 0) ||
        !std::isfinite(c.value) || !(c.atSeconds >= 0)) {
      throw InputError("--speed-at: worker " + std::to_string(c.worker) +
                       " is not one of the workers, or its time or speed is not positive");
    }
  }
  for (const FaultInjection& f : o.faults) {
    if (f.kind == FaultInjection::Kind::Corrupt) {
      throw InputError("--inject-fault: corrupt workers are not simulated (a simulated worker "
                       "renders no colours to check); crash and hang are");
    }
  }
  if (!(o.mtbfSeconds >= 0) || !std::isfinite(o.mtbfSeconds)) {
    throw InputError("--mtbf must be a positive number of seconds");
  }
  if (!(o.failShare >= 0 && o.failShare <= 1)) {
    throw InputError("--fail-share must be a fraction in [0, 1]");
  }
  if (!(o.repairSeconds >= 0) || !std::isfinite(o.repairSeconds)) {
    throw InputError("--repair must be a positive number of seconds");
  }
  if (o.repairSeconds > 0 && !o.joins.empty()) {
    throw InputError("--repair and --join-at cannot be combined: machines that come back join "
                     "after every other worker");
  }
  if (!(o.failAtSeconds >= 0) || !std::isfinite(o.failAtSeconds)) {
    throw InputError("--fail-at must be a time in seconds, 0 or more");
  }
  if (!(o.checkpointEverySeconds >= 0) || !std::isfinite(o.checkpointEverySeconds) ||
      !(o.checkpointSecondsPerPixel >= 0) || !std::isfinite(o.checkpointSecondsPerPixel)) {
    throw InputError("--checkpoint-every and the checkpoint's cost must be 0 or more seconds");
  }
  validateNetworkOptions(o.network);
}

}  // namespace prt
