#pragma once
// Counter-based random numbers. A value depends only on (key, counter), never on which thread
// or process draws it or in what order pixels are rendered, so an image is bit-identical
// whatever the scheduling. Keys are derived along the path: pixel -> sample -> each ray spawned
// (child(i)), so every branch of a distributed-ray-tracing tree has its own stream.
// A Rng is a small value; copy it freely. Not shared between threads.

#include <cstdint>

namespace prt {

// A strong 64-bit bit mixer (the finaliser of SplitMix64 / Stafford's Mix13).
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  constexpr explicit Rng(uint64_t key) : key_(mix64(key ^ 0x9e3779b97f4a7c15ULL)) {}

  // The stream for one sample of one pixel.
  static constexpr Rng forSample(uint64_t pixel, uint32_t sample) {
    return Rng(mix64(pixel * 0x100000001b3ULL + 0x51ed270b27a3b1c5ULL) ^ sample);
  }

  // An independent stream for the i-th ray spawned from this path position.
  constexpr Rng child(uint64_t i) const { return Rng(key_ ^ mix64(i + 0x632be59bd9b4e019ULL)); }

  // Uniform double in [0, 1), 53 random bits.
  constexpr double uniform() {
    const uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++counter_);
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
  }

  // Moves past the next `draws` values, as that many calls of uniform() would.
  constexpr void skip(uint64_t draws) { counter_ += draws; }

  constexpr uint64_t key() const { return key_; }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

}  // namespace prt
