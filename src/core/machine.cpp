#include "core/machine.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <fstream>

#include "core/parallel.h"

namespace prt {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
    }
  }
  return "unknown CPU";
}

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "unknown host";
  return name;
}

std::string describeMachine() {
  std::string text =
      cpuModel() + ", " + std::to_string(hardwareThreads()) + " cores, host " + hostName();
  struct utsname system {};
  if (::uname(&system) == 0) {
    text += std::string(", ") + system.sysname + " " + system.release + " " + system.machine;
  }
  return text;
}

}  // namespace prt
