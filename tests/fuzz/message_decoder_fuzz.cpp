// libFuzzer target: the message decoder on arbitrary bytes. A malformed buffer must end in a
// std::runtime_error (never a crash, an out-of-bounds read, a huge allocation or a leak), and
// a buffer that decodes must encode back to a buffer that decodes to the same bytes again.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "cluster/messages.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  prt::Message message;
  try {
    message = prt::decode(data, size);
  } catch (const std::runtime_error&) {
    return 0;
  }
  const prt::Bytes encoded = prt::encode(message);
  if (prt::encode(prt::decode(encoded)) != encoded) std::abort();
  return 0;
}
