#include "sim/network_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/check.h"
#include "core/input_error.h"

namespace prt {

// Bounds far beyond any network (a latency of 1000 s, 1 kbit/s), within which no simulated
// time overflows into numbers that mean nothing.
void validateNetworkOptions(const NetworkOptions& o) {
  if (!(o.latencySeconds >= 0 && o.latencySeconds <= 1e3)) {
    throw InputError("--latency-us must be in [0, 1e9]");
  }
  if (!(o.bandwidthBytesPerSecond >= 125 && o.bandwidthBytesPerSecond <= 1.25e15)) {
    throw InputError("--bandwidth-mbps must be in [0.001, 1e10]");
  }
  if (!(o.masterServiceSeconds >= 0 && o.masterServiceSeconds <= 1e3)) {
    throw InputError("--master-service-us must be in [0, 1e9]");
  }
}

uint64_t messageBytes(const Message& message) {
  const uint64_t encoded = encode(message).size();
  if (const auto* r = std::get_if<ResultsMsg>(&message); r && r->rgb.empty()) {
    return encoded + 3 * sizeof(float) * r->tasks.size();
  }
  return encoded;
}

NetworkModel::NetworkModel(int workerCount, NetworkOptions options)
    : options_(options),
      outFree_(static_cast<size_t>(workerCount) + 1, 0.0),
      inFree_(static_cast<size_t>(workerCount) + 1, 0.0) {
  PRT_CHECK(workerCount >= 1);
}

double NetworkModel::transmitSeconds(uint64_t bytes) const {
  return static_cast<double>(bytes) / options_.bandwidthBytesPerSecond;
}

double NetworkModel::depart(int from, uint64_t bytes, double now) {
  double& free = outFree_[linkOf(from)];
  const double start = std::max(now, free);
  free = start + transmitSeconds(bytes);
  return start + options_.latencySeconds;
}

double NetworkModel::arrive(int to, uint64_t bytes, double now) {
  double& free = inFree_[linkOf(to)];
  const double start = std::max(now, free);
  free = start + transmitSeconds(bytes);
  return free;
}

}  // namespace prt
