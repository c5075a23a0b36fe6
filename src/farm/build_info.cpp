#include "farm/build_info.h"

#include "trace/isa_level.h"

namespace prt {

namespace {
constexpr const char* kVersion = "0.1.0";
}

std::string prtVersion() { return kVersion; }

// Parsed by versionOf below and by kernelsOf (cluster/messages.h), for the report.
std::string buildDescription() {
  return std::string("prt ") + kVersion + " (trace kernels: " + traceIsaLevel() + ")";
}

std::string versionOf(const std::string& build) {
  if (build.rfind("prt ", 0) != 0) return "";
  const size_t end = build.find(' ', 4);
  return build.substr(4, end == std::string::npos ? std::string::npos : end - 4);
}

}  // namespace prt
