#pragma once
// Which build of the trace library this process runs: "baseline" (any processor of the
// architecture) or an x86-64 level such as "x86-64-v3", picked by the dynamic loader from the
// levels built (CMake's PRT_ISA_LEVELS) and the processor's features. Every build renders
// every pixel bit for bit alike; only the speed differs.

namespace prt {

const char* traceIsaLevel();

}  // namespace prt
