#pragma once
// The memory budget: how much one prt process lets the files it reads make it allocate —
// a file's bytes, the elements a model file declares, a foreign reader's whole import — before
// it refuses with a message instead of growing until the system kills it (a model file that
// declares a billion vertices in a few bytes, /dev/zero given as a mesh).
//
// Default: three quarters of the machine's physical memory, or of the address-space limit
// (ulimit -v) where that is lower; `--max-memory SIZE` sets it (parseByteSize). Thread-safe.

#include <cstdint>
#include <optional>
#include <string>

namespace prt {

uint64_t memoryBudgetBytes();
void setMemoryBudgetBytes(uint64_t bytes);  // 0: back to the default

// "512M", "4G", "1.5GiB", "1000000" (bytes): the size, or nothing for text that is not one
// (a number that is not finite or positive, an unknown unit).
std::optional<uint64_t> parseByteSize(const std::string& text);

// "1.5 GiB", "312 MiB", "20 kiB", "12 bytes".
std::string formatMemorySize(uint64_t bytes);

}  // namespace prt
