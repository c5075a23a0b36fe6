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
