#include "sim/network_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/check.h"
#include "core/input_error.h"

namespace prt {

void validateNetworkOptions(const NetworkOptions& o) {
  if (!(o.latencySeconds >= 0) || !std::isfinite(o.latencySeconds)) {
    throw InputError("--latency-us must be finite and >= 0");
  }
  if (!(o.bandwidthBytesPerSecond > 0) || !std::isfinite(o.bandwidthBytesPerSecond)) {
    throw InputError("--bandwidth-mbps must be finite and positive");
  }
  if (!(o.masterServiceSeconds >= 0) || !std::isfinite(o.masterServiceSeconds)) {
    throw InputError("--master-service-us must be finite and >= 0");
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
