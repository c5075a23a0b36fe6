#include "balance/task_split.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/check.h"
#include "core/input_error.h"

namespace prt {

std::vector<TaskSet> splitEvenly(const TaskSet& tasks, uint64_t parts) {
  PRT_CHECK(parts >= 1);
  TaskSet rest = tasks;
  const uint64_t base = tasks.size() / parts;
  const uint64_t larger = tasks.size() % parts;  // this many pieces get one more
  std::vector<TaskSet> pieces;
  pieces.reserve(static_cast<size_t>(parts));
  for (uint64_t i = 0; i < parts; ++i) pieces.push_back(rest.takeFront(base + (i < larger)));
  PRT_CHECK(rest.empty());
  return pieces;
}

bool LiveWorkers::isLive(int worker) const {
  return worker >= 0 && worker < workerCount() && live_[static_cast<size_t>(worker)];
}

void LiveWorkers::markLost(int worker) {
  if (isLive(worker)) {
    live_[static_cast<size_t>(worker)] = false;
    --liveCount_;
  }
}

std::vector<int> LiveWorkers::liveList() const {
  std::vector<int> out;
  for (int w = 0; w < workerCount(); ++w) {
    if (isLive(w)) out.push_back(w);
  }
  return out;
}

Decisions spreadOverLiveWorkers(const TaskSet& tasks, const LiveWorkers& workers) {
  const std::vector<int> live = workers.liveList();
  if (live.empty() || tasks.empty()) return {};
  std::vector<TaskSet> pieces = splitEvenly(tasks, live.size());
  Decisions out;
  for (size_t i = 0; i < live.size(); ++i) {
    if (!pieces[i].empty()) out.push_back(Assign{live[i], std::move(pieces[i])});
  }
  return out;
}

void validateStartInfo(const StartInfo& info) {
  if (info.speedIndexSeconds.empty()) throw InputError("a strategy needs at least one worker");
  for (size_t w = 0; w < info.speedIndexSeconds.size(); ++w) {
    const double s = info.speedIndexSeconds[w];
    if (!(std::isfinite(s) && s > 0)) {
      throw InputError("speed index of worker " + std::to_string(w) + " is " + std::to_string(s) +
                       "; it must be a positive number of seconds");
    }
  }
}

void validateJoin(int worker, int current, double speedIndexSeconds) {
  if (worker != current) {
    throw InputError("worker " + std::to_string(worker) + " cannot join: the next worker is " +
                     std::to_string(current));
  }
  if (!(std::isfinite(speedIndexSeconds) && speedIndexSeconds > 0)) {
    throw InputError("speed index of joining worker " + std::to_string(worker) + " is " +
                     std::to_string(speedIndexSeconds) +
                     "; it must be a positive number of seconds");
  }
}

}  // namespace prt
