#include "cluster/spot_checks.h"

#include <algorithm>
#include <cstring>

#include "core/check.h"

namespace prt {
namespace {

uint64_t mix(uint64_t x) {  // splitmix64's finaliser
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Pixel p's draw in [0, 1), the same for every run with this seed.
double draw(uint64_t seed, uint64_t pixel) {
  return static_cast<double>(mix(seed ^ mix(pixel)) >> 11) * 0x1p-53;
}

bool sameBits(const Rgb& a, const float* b) { return std::memcmp(a.data(), b, sizeof a) == 0; }

}  // namespace

SpotChecks::SpotChecks(SpotCheckOptions options, int workerCount)
    : options_(options),
      passes_(static_cast<size_t>(workerCount), 0),
      eligibleIndex_(static_cast<size_t>(workerCount), -1),
      waiting_(static_cast<size_t>(workerCount)) {
  PRT_CHECK(options_.percent >= 0 && options_.percent <= 100);
}

void SpotChecks::addWorker() {
  passes_.push_back(0);
  eligibleIndex_.push_back(-1);
  waiting_.emplace_back();
}

void SpotChecks::setEligible(int worker, bool eligible) {
  const auto w = static_cast<size_t>(worker);
  PRT_CHECK(w < eligibleIndex_.size());
  const int at = eligibleIndex_[w];
  if (eligible && at < 0) {
    eligibleIndex_[w] = static_cast<int>(eligible_.size());
    eligible_.push_back(worker);
  } else if (!eligible && at >= 0) {
    const int last = eligible_.back();
    eligible_[static_cast<size_t>(at)] = last;
    eligibleIndex_[static_cast<size_t>(last)] = at;
    eligible_.pop_back();
    eligibleIndex_[w] = -1;
  }
}

double SpotChecks::rateFor(int worker) const {
  const double rate = options_.percent / 100;
  if (rate >= 1) return 1;  // --verify 100: every pixel, trusted or not
  const int passed = passes_[static_cast<size_t>(worker)];
  if (passed < kNewPasses) return std::min(1.0, 4 * rate);
  if (passed >= kTrustedPasses) return lowestRate(options_.percent);
  return rate;
}

// The next eligible worker in turn that is not the author; the referee when there is none.
int SpotChecks::chooseChecker(int author) {
  for (size_t tries = 0; tries < 2 && !eligible_.empty(); ++tries) {
    const int c = eligible_[turn_++ % eligible_.size()];
    if (c != author) return c;
  }
  return kReferee;
}

std::vector<uint64_t>& SpotChecks::waitingFor(int checker) {
  return checker == kReferee ? refereeWaiting_ : waiting_[static_cast<size_t>(checker)];
}

void SpotChecks::queueFor(int checker, uint64_t pixel) {
  std::vector<uint64_t>& list = waitingFor(checker);
  if (list.empty()) checkersWaiting_.push_back(checker);
  list.push_back(pixel);
}

uint64_t SpotChecks::sample(int author, const TaskSet& tasks, const std::vector<float>& rgb) {
  if (!enabled() || tasks.empty()) return 0;
  PRT_CHECK(rgb.size() == 3 * tasks.size());
  const double rate = rateFor(author);
  const bool atLeastOne = passes_[static_cast<size_t>(author)] < kNewPasses;
  uint64_t chosen = 0, least = 0;
  size_t i = 0, leastAt = 0;
  double leastDraw = 2;
  const auto open = [&](uint64_t pixel, size_t at) {
    Open o;
    o.author = author;
    o.checker = chooseChecker(author);
    std::memcpy(o.rgb.data(), &rgb[3 * at], sizeof o.rgb);
    open_[pixel] = o;  // a pixel is open once: it is delivered again only once taken back
    queueFor(o.checker, pixel);
    ++chosen;
  };
  tasks.forEach([&](uint64_t pixel) {
    const double d = draw(options_.seed, pixel);
    if (d < rate) open(pixel, i);
    if (d < leastDraw) {
      leastDraw = d;
      least = pixel;
      leastAt = i;
    }
    ++i;
  });
  if (chosen == 0 && atLeastOne) open(least, leastAt);
  return chosen;
}

TaskSet SpotChecks::take(int checker, double now) {
  std::vector<uint64_t>& list = waitingFor(checker);
  std::sort(list.begin(), list.end());
  TaskSet out;
  for (const uint64_t pixel : list) {
    auto it = open_.find(pixel);
    // Only what is still open and still this checker's (workerGone may have moved it).
    if (it == open_.end() || it->second.checker != checker || it->second.sent) continue;
    it->second.sent = true;
    it->second.sentAt = now;
    out.append(TaskRun{pixel, 1, 1});
  }
  list.clear();
  checkersWaiting_.erase(std::remove(checkersWaiting_.begin(), checkersWaiting_.end(), checker),
                         checkersWaiting_.end());
  return out;
}

std::vector<Disagreement> SpotChecks::results(int checker, const TaskSet& tasks,
                                              const std::vector<float>& rgb) {
  PRT_CHECK(rgb.size() == 3 * tasks.size());
  std::vector<Disagreement> out;
  size_t i = 0;
  tasks.forEach([&](uint64_t pixel) {
    const float* mine = &rgb[3 * i++];
    auto it = open_.find(pixel);
    if (it == open_.end() || it->second.checker != checker || !it->second.sent) return;
    const Open o = it->second;
    open_.erase(it);
    if (checker == kReferee) ++byReferee_;
    if (sameBits(o.rgb, mine)) {
      ++verified_;
      ++passes_[static_cast<size_t>(o.author)];
      return;
    }
    Disagreement d{pixel, o.author, checker, o.rgb, {}};
    std::memcpy(d.checkerRgb.data(), mine, sizeof d.checkerRgb);
    out.push_back(d);
  });
  return out;
}

std::vector<uint64_t> SpotChecks::openPixels() const {
  std::vector<uint64_t> out;
  out.reserve(open_.size());
  for (const auto& entry : open_) out.push_back(entry.first);
  std::sort(out.begin(), out.end());
  return out;
}

uint64_t SpotChecks::expire(double now, double seconds) {
  std::vector<uint64_t> overdue;
  for (const auto& [pixel, o] : open_) {
    if (o.sent && o.checker != kReferee && now - o.sentAt > seconds) overdue.push_back(pixel);
  }
  std::sort(overdue.begin(), overdue.end());
  for (const uint64_t pixel : overdue) {
    Open& o = open_[pixel];
    o.checker = kReferee;
    o.sent = false;
    queueFor(kReferee, pixel);
  }
  return overdue.size();
}

void SpotChecks::workerGone(int worker, bool rejected) {
  setEligible(worker, false);
  waiting_[static_cast<size_t>(worker)].clear();
  checkersWaiting_.erase(std::remove(checkersWaiting_.begin(), checkersWaiting_.end(), worker),
                         checkersWaiting_.end());
  std::vector<uint64_t> moved;
  for (auto it = open_.begin(); it != open_.end();) {
    Open& o = it->second;
    if (rejected && o.author == worker) {
      it = open_.erase(it);
      continue;
    }
    if (o.checker == worker) moved.push_back(it->first);
    ++it;
  }
  std::sort(moved.begin(), moved.end());  // the same order, whatever the map's
  for (const uint64_t pixel : moved) {
    Open& o = open_[pixel];
    o.checker = chooseChecker(o.author);
    o.sent = false;
    queueFor(o.checker, pixel);
  }
}

}  // namespace prt
