// libFuzzer target: the checkpoint reader (farm/checkpoint.h) on checkpoints made by hand.
// The input's first two bytes choose the image (1..64 by 1..64 pixels); the rest is the
// file's body after its header (the runs, the colours, the owners), closed with a valid
// checksum, so the fuzzer reaches what a checksum cannot protect against: a file someone
// made. Bytes that are not a checkpoint of that image must end in an InputError; a checkpoint
// that is read must hold only pixels inside the image, ascending, with finite colours.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/input_error.h"
#include "farm/checkpoint.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void put(std::vector<uint8_t>& out, const void* data, size_t size) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  out.insert(out.end(), bytes, bytes + size);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  prt::CheckpointKey key;
  key.hash = 0x5052544655555a5aull;
  key.description = "fuzz";
  key.width = 1 + data[0] % 64;
  key.height = 1 + data[1] % 64;
  std::vector<uint8_t> bytes;
  put(bytes, "PRTCKPT1", 8);
  put(bytes, &key.hash, 8);
  const uint16_t length = 4;
  put(bytes, &length, 2);
  put(bytes, key.description.data(), 4);
  const int32_t dimensions[] = {key.width, key.height};
  put(bytes, dimensions, sizeof dimensions);
  put(bytes, data + 2, size - 2);
  uint64_t hash = 14695981039346656037ull;
  for (const uint8_t b : bytes) {
    hash ^= b;
    hash *= 1099511628211ull;
  }
  put(bytes, &hash, 8);
  prt::Checkpoint c;
  try {
    c = prt::parseCheckpoint(bytes, key, "fuzz.ckpt");
  } catch (const prt::InputError&) {
    return 0;
  }
  const uint64_t pixels = static_cast<uint64_t>(key.width) * static_cast<uint64_t>(key.height);
  check(c.done.allBelow(pixels) && c.done.size() <= pixels);
  check(c.owner.size() == pixels && c.image.pixelCount() == pixels);
  int64_t previous = -1;
  c.done.forEach([&](uint64_t p) {
    check(static_cast<int64_t>(p) > previous);
    previous = static_cast<int64_t>(p);
    const prt::Color colour = c.image.at(p);
    check(std::isfinite(colour.x) && std::isfinite(colour.y) && std::isfinite(colour.z));
    check(c.owner[p] >= -1);
  });
  return 0;
}
