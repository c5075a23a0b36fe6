#include "core/speed_schedule.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/input_error.h"

namespace prt {
namespace {

bool parseNumber(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

}  // namespace

std::vector<SpeedChange> parseSpeedChanges(const std::string& text, const std::string& flag,
                                           int workers, double minValue) {
  std::vector<SpeedChange> out;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    auto bad = [&](const std::string& why) {
      return InputError(flag + ": '" + item + "' " + why + " (expected W:T:" +
                        (minValue > 0 ? "K" : "SPEED") + ", W:T:...)");
    };
    const size_t a = item.find(':');
    const size_t b = a == std::string::npos ? a : item.find(':', a + 1);
    if (b == std::string::npos || item.find(':', b + 1) != std::string::npos) {
      throw bad("is not three numbers separated by ':'");
    }
    double worker = 0;
    SpeedChange c;
    if (!parseNumber(item.substr(0, a), worker) || worker != std::floor(worker) || worker < 0 ||
        worker >= workers) {
      throw bad("names no worker; workers are 0 to " + std::to_string(workers - 1));
    }
    c.worker = static_cast<int>(worker);
    if (!parseNumber(item.substr(a + 1, b - a - 1), c.atSeconds) || c.atSeconds < 0) {
      throw bad("has no time >= 0 seconds");
    }
    const bool valueOk = parseNumber(item.substr(b + 1), c.value) &&
                         (minValue > 0 ? c.value >= minValue : c.value > minValue);
    if (!valueOk) {
      throw bad(minValue > 0 ? "has no slowdown >= " + std::to_string(static_cast<int>(minValue))
                             : std::string("has no speed > 0"));
    }
    out.push_back(c);
  }
  if (out.empty()) throw InputError(flag + ": no changes given");
  if (text.back() == ',') throw InputError(flag + ": '" + text + "' ends with an empty item");
  return out;
}

std::vector<JoinWave> parseJoinWaves(const std::string& text, const std::string& flag) {
  std::vector<JoinWave> out;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    auto bad = [&](const std::string& why) {
      return InputError(flag + ": '" + item + "' " + why + " (expected T:K, T:K,...)");
    };
    const size_t a = item.find(':');
    if (a == std::string::npos || item.find(':', a + 1) != std::string::npos) {
      throw bad("is not two numbers separated by ':'");
    }
    JoinWave w;
    if (!parseNumber(item.substr(0, a), w.atSeconds) || !(w.atSeconds >= 0) ||
        !(w.atSeconds <= kMaxJoinSeconds)) {
      throw bad("has no time in [0, " + std::to_string(static_cast<int>(kMaxJoinSeconds)) +
                "] seconds");
    }
    double count = 0;
    if (!parseNumber(item.substr(a + 1), count) || count != std::floor(count) || count < 1 ||
        count > kMaxJoinWave) {
      throw bad("has no worker count in [1, " + std::to_string(kMaxJoinWave) + "]");
    }
    w.count = static_cast<int>(count);
    out.push_back(w);
  }
  if (out.empty()) throw InputError(flag + ": no arrivals given");
  if (text.back() == ',') throw InputError(flag + ": '" + text + "' ends with an empty item");
  std::stable_sort(out.begin(), out.end(),
                   [](const JoinWave& x, const JoinWave& y) { return x.atSeconds < y.atSeconds; });
  return out;
}

void validateJoinWaves(const std::vector<JoinWave>& waves, const std::string& flag) {
  for (size_t i = 0; i < waves.size(); ++i) {
    const JoinWave& j = waves[i];
    if (!(j.atSeconds >= 0 && j.atSeconds <= kMaxJoinSeconds) || j.count < 1 ||
        j.count > kMaxJoinWave) {
      std::ostringstream wave;
      wave << j.atSeconds << ':' << j.count;
      throw InputError(flag + " " + wave.str() +
                       ": the time must be in [0, " +
                       std::to_string(static_cast<int>(kMaxJoinSeconds)) +
                       "] seconds and the count in [1, " + std::to_string(kMaxJoinWave) + "]");
    }
    if (i > 0 && j.atSeconds < waves[i - 1].atSeconds) {
      throw InputError(flag + ": the waves must be in time order");
    }
  }
}

int joinerCount(const std::vector<JoinWave>& waves) {
  int n = 0;
  for (const JoinWave& w : waves) n += w.count;
  return n;
}

std::vector<SpeedChange> changesOf(const std::vector<SpeedChange>& changes, int worker) {
  std::vector<SpeedChange> out;
  for (const SpeedChange& c : changes) {
    if (c.worker == worker) out.push_back(c);
  }
  std::stable_sort(out.begin(), out.end(), [](const SpeedChange& x, const SpeedChange& y) {
    return x.atSeconds < y.atSeconds;
  });
  return out;
}

double valueAt(const std::vector<SpeedChange>& sorted, double initial, double seconds) {
  double value = initial;
  for (const SpeedChange& c : sorted) {
    if (c.atSeconds > seconds) break;
    value = c.value;
  }
  return value;
}

}  // namespace prt
