#pragma once
// Speeds that change mid-run: a list of changes "worker W becomes X from T seconds after the
// start", as the command line gives them (`--slowdown-at W:T:K,...` for the thread and MPI
// drivers, K a slowdown factor >= 1; `prt simulate --speed-at W:T:SPEED,...`, SPEED a
// relative speed > 0). What X means is the caller's; this header parses, checks and looks up.
// Also the arrivals of workers mid-run (`--join-at T:K,...`: K more workers T seconds in).
// Plain values; thread-safe.

#include <string>
#include <vector>

namespace prt {

struct SpeedChange {
  int worker = 0;
  double atSeconds = 0;  // from the start of the run, >= 0
  double value = 1;      // the new slowdown factor or speed, from then on
  bool operator==(const SpeedChange&) const = default;
};

// Parses "W:T:X,W:T:X,...". Throws InputError (naming `flag` and the offending item) for a
// malformed item, a worker outside [0, workers), a negative or non-finite T, or X below
// `minValue` (or not above it when minValue is 0, so speeds must be > 0) or not finite.
std::vector<SpeedChange> parseSpeedChanges(const std::string& text, const std::string& flag,
                                           int workers, double minValue);

// --join-at T:K: K more workers join the running render T seconds after it starts.
struct JoinWave {
  double atSeconds = 0;
  int count = 1;
  bool operator==(const JoinWave&) const = default;
};

inline constexpr double kMaxJoinSeconds = 86400;
inline constexpr int kMaxJoinWave = 4096;

// Parses "T:K,T:K,..." and sorts the waves by time (joiners are numbered in the order they
// join). Throws InputError (naming `flag` and the item) for a malformed item, T outside
// [0, kMaxJoinSeconds] or K outside [1, kMaxJoinWave].
std::vector<JoinWave> parseJoinWaves(const std::string& text, const std::string& flag);
// Throws InputError (naming `flag`) unless every wave is in those ranges and the waves are in
// time order, as the drivers number joiners: what parseJoinWaves returns always passes.
void validateJoinWaves(const std::vector<JoinWave>& waves, const std::string& flag);
int joinerCount(const std::vector<JoinWave>& waves);

// Worker `worker`'s changes, sorted by time (a later item wins at equal times).
std::vector<SpeedChange> changesOf(const std::vector<SpeedChange>& changes, int worker);

// The value in force `seconds` after the start: the last of `sorted` (one worker's, from
// changesOf) at or before it, else `initial`.
double valueAt(const std::vector<SpeedChange>& sorted, double initial, double seconds);

}  // namespace prt
