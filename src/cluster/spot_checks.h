#pragma once
// SpotChecks: the master's checks of the pixels workers deliver. PRT's images are bit-identical
// by construction — any worker, any thread count, any driver renders a pixel to the same bits
// — so one pixel rendered again elsewhere is an exact test of the worker that delivered it: a
// single differing bit means one of the two renders is wrong, and a correct worker can never
// fail one.
//
// Policy, per worker, by the checks it has passed (its standing):
//   new       fewer than kNewPasses passes: 4 times the rate, and at least one pixel of every
//             batch it delivers;
//   regular   the rate (--verify PERCENT, 1 % by default);
//   trusted   kTrustedPasses passes or more: half the rate (but 100 % stays every pixel).
// Which pixels: pixel p is sampled when a hash of (seed, p) falls below the rate; a new
// worker's batch with none below it gives its pixel of least hash. The sample therefore
// depends on the seed, the pixels and the worker's standing, never on the clock.
// Who checks: another eligible worker (live, set up, not rejected), taken in turn, and sent
// when the master next hears from it or at once when it is idle (CheckMsg: it renders them
// before its next batch); with none eligible the master renders the pixel itself (kReferee).
// A disagreement between two workers is settled by a third render, the master's own: whoever
// differs from it is wrong (see Master::settle).
// Pure bookkeeping: no I/O, no clock. Not thread-safe: one master owns it.

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "cluster/messages.h"

namespace prt {

struct SpotCheckOptions {
  double percent = 1;     // of the pixels each worker delivers; 0: no checks
  uint64_t seed = 0x5eed;  // which pixels: the same seed, the same sample
};

using Rgb = std::array<float, 3>;

// Two renders of one pixel that differ.
struct Disagreement {
  uint64_t pixel = 0;
  int author = 0;   // the worker whose result is in the image
  int checker = 0;  // the one that rendered it again (kReferee: the master)
  Rgb authorRgb{}, checkerRgb{};
};

class SpotChecks {
 public:
  static constexpr int kNewPasses = 3;
  static constexpr int kTrustedPasses = 32;
  static constexpr int kReferee = kMaster;  // the master renders the check itself

  SpotChecks(SpotCheckOptions options, int workerCount);
  bool enabled() const { return options_.percent > 0; }
  void addWorker();  // a joiner: new, not yet eligible

  // Who may check others (the master says so as workers are set up, lost or rejected).
  void setEligible(int worker, bool eligible);

  // Chooses the pixels of a batch `author` delivered (fresh pixels `tasks`, colours `rgb`)
  // to check and gives each a checker. Returns how many were chosen.
  uint64_t sample(int author, const TaskSet& tasks, const std::vector<float>& rgb);
  // Workers with checks waiting to be sent (kReferee included), in the order they got them.
  const std::vector<int>& checkersWaiting() const { return checkersWaiting_; }
  // The checks waiting for `checker`, now sent (at `now`, on the master's clock).
  TaskSet take(int checker, double now = 0);
  // Checks sent more than `seconds` before `now` and not answered go to the referee: a checker
  // that is there but never answers cannot hold the run up. Returns how many.
  uint64_t expire(double now, double seconds);

  // Renders of checked pixels by `checker`: a match is a pass for the pixel's author; a
  // mismatch is returned for the master to settle. Pixels not asked of `checker` (a check
  // moved to another worker meanwhile, or never asked) are ignored.
  std::vector<Disagreement> results(int checker, const TaskSet& tasks,
                                    const std::vector<float>& rgb);

  // `worker` is gone: the checks it was to render go to another checker; when it was
  // rejected, the checks of its own pixels are dropped too (they are taken back).
  void workerGone(int worker, bool rejected);

  bool idle() const { return open_.empty(); }  // no check open
  std::vector<uint64_t> openPixels() const;      // the pixels of open checks, ascending
  uint64_t openChecks() const { return open_.size(); }
  uint64_t verifiedPixels() const { return verified_; }  // checks that matched
  uint64_t refereeChecks() const { return byReferee_; }  // of all checks, those the master rendered
  int passes(int worker) const { return passes_[static_cast<size_t>(worker)]; }
  // The rate at which `worker`'s pixels are sampled now (0..1).
  double rateFor(int worker) const;
  // The lowest rate any worker's pixels are sampled at, a trusted worker's (0..1): each pixel
  // a worker delivers is checked with at least this probability.
  static double lowestRate(double percent) { return percent >= 100 ? 1 : percent / 200; }

 private:
  struct Open {
    int author = 0;
    int checker = 0;
    bool sent = false;
    double sentAt = 0;
    Rgb rgb{};  // what the author delivered
  };
  int chooseChecker(int author);
  void queueFor(int checker, uint64_t pixel);
  std::vector<uint64_t>& waitingFor(int checker);

  SpotCheckOptions options_;
  std::vector<int> passes_;
  std::vector<int> eligibleIndex_;  // per worker: its place in eligible_, or -1
  std::vector<int> eligible_;       // eligible workers, in no particular order
  uint64_t turn_ = 0;               // round-robin over eligible_
  std::unordered_map<uint64_t, Open> open_;  // by pixel
  std::vector<std::vector<uint64_t>> waiting_;  // per worker: checks not sent yet
  std::vector<uint64_t> refereeWaiting_;
  std::vector<int> checkersWaiting_;
  uint64_t verified_ = 0;
  uint64_t byReferee_ = 0;
};

}  // namespace prt
