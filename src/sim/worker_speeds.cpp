#include "sim/worker_speeds.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "core/input_error.h"

namespace prt {
namespace {

// A uniform double in (0, 1): 53 random bits, never 0 (log(0) in Box-Muller).
double unitOpen(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

void validateWorkerSpeeds(const std::vector<double>& speeds, int workers) {
  if (speeds.size() != static_cast<size_t>(workers)) {
    throw InputError("--speeds lists " + std::to_string(speeds.size()) + " values for " +
                     std::to_string(workers) + " workers; give one per worker");
  }
  for (double s : speeds) {
    if (!(s > 0) || !std::isfinite(s)) {
      throw InputError("worker speeds must be finite and positive (got " + number(s) +
                       "); 1 is full speed, 0.5 twice as slow");
    }
  }
}

std::vector<double> uniformSpeeds(int workers) {
  return std::vector<double>(static_cast<size_t>(workers), 1.0);
}

std::vector<double> slowShareSpeeds(int workers, double share, double factor, uint64_t seed) {
  if (!(share >= 0 && share <= 1)) {
    throw InputError("--slow-share must be a fraction of the workers in [0, 1] (got " +
                     number(share) + ")");
  }
  if (!(factor >= 1) || !std::isfinite(factor)) {
    throw InputError("--slow-factor must be finite and at least 1 (got " + number(factor) + ")");
  }
  std::vector<int> order(static_cast<size_t>(workers));
  for (int w = 0; w < workers; ++w) order[static_cast<size_t>(w)] = w;
  std::mt19937_64 rng(seed);
  for (size_t i = order.size(); i > 1; --i) {  // Fisher-Yates
    std::swap(order[i - 1], order[static_cast<size_t>(rng() % i)]);
  }
  const auto slow = static_cast<size_t>(std::lround(share * workers));
  std::vector<double> speeds = uniformSpeeds(workers);
  for (size_t i = 0; i < slow; ++i) speeds[static_cast<size_t>(order[i])] = 1.0 / factor;
  return speeds;
}

std::vector<double> lognormalSpeeds(int workers, double sigma, uint64_t seed) {
  if (!(sigma >= 0) || !std::isfinite(sigma)) {
    throw InputError("--lognormal sigma must be finite and >= 0 (got " + number(sigma) + ")");
  }
  std::mt19937_64 rng(seed);
  std::vector<double> speeds(static_cast<size_t>(workers));
  for (double& s : speeds) {
    const double z = std::sqrt(-2 * std::log(unitOpen(rng))) *
                     std::cos(2 * std::numbers::pi * unitOpen(rng));  // Box-Muller
    s = std::exp(sigma * z);
  }
  return speeds;
}

double workDoneAt(double start, double work, double initial, const std::vector<SpeedChange>& sorted) {
  double t = start;
  double speed = valueAt(sorted, initial, start);
  for (const SpeedChange& c : sorted) {
    if (c.atSeconds <= t) continue;
    const double capacity = (c.atSeconds - t) * speed;  // work done before the next change
    if (capacity >= work) break;
    work -= capacity;
    t = c.atSeconds;
    speed = c.value;
  }
  return t + work / speed;
}

}  // namespace prt
