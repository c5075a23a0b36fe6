#pragma once
// parallelFor: the one place PRT runs work on several threads inside a process. Rendering code
// calls this and never creates threads itself. Backed by oneTBB; `threads` <= 0 means all
// hardware threads. Blocks until every index in [0, count) has run. fn(i) must be safe to call
// concurrently for different i.

#include <cstdint>
#include <functional>

namespace prt {

int hardwareThreads();
void parallelFor(uint64_t count, int threads, const std::function<void(uint64_t)>& fn);

}  // namespace prt
