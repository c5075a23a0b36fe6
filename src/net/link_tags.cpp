#include "net/link_tags.h"

#include <algorithm>
#include <cstring>

namespace prt {

Bytes releaseMessage(int32_t code, const std::string& wakePort) {
  Bytes out(sizeof code + wakePort.size());
  std::memcpy(out.data(), &code, sizeof code);
  if (!wakePort.empty()) std::memcpy(out.data() + sizeof code, wakePort.data(), wakePort.size());
  return out;
}

Bytes withHeader(int32_t a, int32_t b, const Bytes& payload) {
  Bytes out(sizeof a + sizeof b + payload.size());
  std::memcpy(out.data(), &a, sizeof a);
  std::memcpy(out.data() + sizeof a, &b, sizeof b);
  std::copy(payload.begin(), payload.end(), out.begin() + sizeof a + sizeof b);
  return out;
}

bool readHeader(const Bytes& bytes, int32_t& a, int32_t& b) {
  if (bytes.size() < sizeof a + sizeof b) return false;
  std::memcpy(&a, bytes.data(), sizeof a);
  std::memcpy(&b, bytes.data() + sizeof a, sizeof b);
  return true;
}

}  // namespace prt
