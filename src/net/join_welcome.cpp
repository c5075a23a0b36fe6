#include "net/join_welcome.h"

#include <cstring>
#include <stdexcept>

#include "core/byte_codec.h"

namespace prt {

Bytes encodeWelcome(const ParallelOptions& o) {
  const auto kind = static_cast<uint8_t>(o.speedIndexKind);
  const auto discs = static_cast<int32_t>(o.speedIndexDiscs);
  const auto batch = static_cast<uint64_t>(o.batchPixels);
  const double timeout = o.workerTimeoutSeconds;
  const double batchSeconds = o.batchSeconds;
  // Laid out by hand, as ByteWriter would (GCC 12 misreads its inlined copies here).
  Bytes out(sizeof kind + sizeof discs + sizeof batch + sizeof timeout + sizeof batchSeconds);
  uint8_t* p = out.data();
  std::memcpy(p, &kind, sizeof kind);
  std::memcpy(p += sizeof kind, &discs, sizeof discs);
  std::memcpy(p += sizeof discs, &batch, sizeof batch);
  std::memcpy(p += sizeof batch, &timeout, sizeof timeout);
  std::memcpy(p + sizeof timeout, &batchSeconds, sizeof batchSeconds);
  return out;
}

// The joiner's side: its endpoint and the run's options over its own (threads, slowdown).
int decodeWelcome(const Bytes& bytes, ParallelOptions& o) {
  ByteReader r(bytes.data(), bytes.size(), "welcome");
  const auto endpoint = r.pod<int32_t>();
  (void)r.pod<int32_t>();
  const auto kind = r.pod<uint8_t>();
  if (kind > static_cast<uint8_t>(SpeedIndexKind::Slowdown)) {
    throw std::runtime_error("malformed welcome: speed index kind");
  }
  o.speedIndexKind = static_cast<SpeedIndexKind>(kind);
  o.speedIndexDiscs = r.pod<int32_t>();
  o.batchPixels = r.pod<uint64_t>();
  o.workerTimeoutSeconds = r.pod<double>();
  o.batchSeconds = r.pod<double>();
  if (endpoint < 0 || o.speedIndexDiscs < 1 || o.batchPixels < 1 ||
      !(o.workerTimeoutSeconds > 0) || !(o.batchSeconds >= 0 && o.batchSeconds <= 60)) {
    throw std::runtime_error("malformed welcome");
  }
  return endpoint;
}

}  // namespace prt
