#include "farm/progress_board.h"

namespace prt {

const char* stateName(WorkerProgress::State state) {
  switch (state) {
    case WorkerProgress::State::Starting: return "starting";
    case WorkerProgress::State::Working: return "working";
    case WorkerProgress::State::Idle: return "idle";
    case WorkerProgress::State::Lost: return "lost";
    case WorkerProgress::State::Done: return "done";
  }
  return "?";
}

const char* phaseName(ProgressSnapshot::Phase phase) {
  switch (phase) {
    case ProgressSnapshot::Phase::Starting: return "starting";
    case ProgressSnapshot::Phase::Rendering: return "rendering";
    case ProgressSnapshot::Phase::Finished: return "finished";
    case ProgressSnapshot::Phase::Failed: return "failed";
  }
  return "?";
}

void ProgressBoard::publish(ProgressSnapshot snapshot) {
  std::lock_guard lock(mutex_);
  snapshot.version = snapshot_.version + 1;
  snapshot_ = std::move(snapshot);
}

void ProgressBoard::publishImage(PartialImage image) {
  auto copy = std::make_shared<const PartialImage>(std::move(image));
  std::lock_guard lock(mutex_);
  image_ = std::move(copy);
  imageWanted_.store(false, std::memory_order_relaxed);
}

ProgressSnapshot ProgressBoard::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

std::shared_ptr<const PartialImage> ProgressBoard::image() {
  imageWanted_.store(true, std::memory_order_relaxed);
  std::lock_guard lock(mutex_);
  return image_;
}

void ProgressBoard::setFacts(RunFacts facts) {
  std::lock_guard lock(mutex_);
  facts_ = std::move(facts);
}

ProgressBoard::RunFacts ProgressBoard::facts() const {
  std::lock_guard lock(mutex_);
  return facts_;
}

}  // namespace prt
