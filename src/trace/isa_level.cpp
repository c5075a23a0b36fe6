#include "trace/isa_level.h"

namespace prt {

const char* traceIsaLevel() {
  return PRT_ISA_LEVEL;
}

}  // namespace prt
