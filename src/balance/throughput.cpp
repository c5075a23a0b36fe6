#include "balance/throughput.h"

#include <algorithm>


namespace prt {

void Throughput::reset(int workerCount) {
  workers_.assign(static_cast<size_t>(workerCount), Worker{});
}

void Throughput::given(int worker, uint64_t tasks) {
  at(worker).held += tasks;
}

void Throughput::moved(int from, int to, uint64_t tasks) {
  const uint64_t count = std::min(tasks, at(from).held);
  at(from).held -= count;
  at(to).held += count;
}

void Throughput::returned(int worker, uint64_t tasks, double seconds) {
  Worker& w = at(worker);
  w.held -= std::min(w.held, tasks);
  if (!(seconds > 0) || tasks == 0) return;  // unmeasured: nothing to learn
  const auto n = static_cast<double>(tasks);
  w.recentTasks = kRecentDecay * w.recentTasks + n;
  w.recentSeconds = kRecentDecay * w.recentSeconds + seconds;
  const double mean = seconds / n;
  w.tasks += n;
  w.seconds += seconds;
  w.sumSquares += n * mean * mean;
  ++w.batches;
  w.chunkTasks += n;
  w.chunkSeconds += seconds;
}

void Throughput::chunkDone(int worker) {
  Worker& w = at(worker);
  w.held = 0;
  if (w.chunkTasks == 0) return;
  ++w.chunks;
  const auto k = static_cast<double>(w.chunks);
  w.wapTasks += k * w.chunkTasks;
  w.wapSeconds += k * w.chunkSeconds;
  w.chunkTasks = 0;
  w.chunkSeconds = 0;
}

void Throughput::lost(int worker) {
  at(worker).held = 0;
}

double Throughput::rate(int worker) const {
  const Worker& w = at(worker);
  return w.recentSeconds > 0 ? w.recentTasks / w.recentSeconds : 0.0;
}

double Throughput::meanTaskSeconds(int worker) const {
  const Worker& w = at(worker);
  return w.tasks > 0 ? w.seconds / w.tasks : 0.0;
}

double Throughput::taskSecondsVariance(int worker) const {
  const Worker& w = at(worker);
  if (w.batches < 2) return 0.0;
  const double mu = w.seconds / w.tasks;
  // sum n (x - mu)^2 = sum n x^2 - N mu^2, over (batches - 1) degrees of freedom.
  const double spread = w.sumSquares - w.tasks * mu * mu;
  return std::max(0.0, spread / static_cast<double>(w.batches - 1));
}

double Throughput::weightedAverageTaskSeconds(int worker) const {
  const Worker& w = at(worker);
  const auto next = static_cast<double>(w.chunks + 1);
  const double tasks = w.wapTasks + next * w.chunkTasks;
  const double seconds = w.wapSeconds + next * w.chunkSeconds;
  return tasks > 0 ? seconds / tasks : 0.0;
}

}  // namespace prt
