#include "cluster/fault_injection.h"

#include <cstring>

namespace prt {

void corruptPixels(const TaskSet& tasks, std::vector<float>& rgb) {
  size_t i = 0;
  tasks.forEach([&](uint64_t pixel) {
    uint64_t h = pixel * 0x9e3779b97f4a7c15ull;
    h ^= h >> 29;
    if (h & 1) {
      uint32_t bits;
      std::memcpy(&bits, &rgb[3 * i], sizeof bits);
      bits ^= 1u << 20;
      std::memcpy(&rgb[3 * i], &bits, sizeof bits);
    }
    ++i;
  });
}

}  // namespace prt
