#include "core/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace prt {
namespace {

std::atomic<uint64_t> chosenBudget{0};

uint64_t defaultBudget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  uint64_t memory = pages > 0 && pageSize > 0
                        ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(pageSize)
                        : uint64_t{4} << 30;
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    memory = std::min<uint64_t>(memory, limit.rlim_cur);
  }
  return memory / 4 * 3;
}

}  // namespace

uint64_t memoryBudgetBytes() {
  const uint64_t chosen = chosenBudget.load();
  if (chosen != 0) return chosen;
  static const uint64_t fallback = defaultBudget();
  return fallback;
}

void setMemoryBudgetBytes(uint64_t bytes) {
  chosenBudget.store(bytes);
}

std::optional<uint64_t> parseByteSize(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || !std::isfinite(value) || value <= 0) return {};
  std::string unit(end);
  for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!unit.empty() && unit.back() == 'b') unit.pop_back();  // "GB", "GiB", "B"
  if (unit.size() == 2 && unit[1] == 'i') unit.pop_back();   // "Gi" as "G"
  double scale = 1;
  if (unit == "k") {
    scale = 1024.0;
  } else if (unit == "m") {
    scale = 1024.0 * 1024;
  } else if (unit == "g") {
    scale = 1024.0 * 1024 * 1024;
  } else if (unit == "t") {
    scale = 1024.0 * 1024 * 1024 * 1024;
  } else if (!unit.empty()) {
    return {};
  }
  const double bytes = value * scale;
  if (bytes < 1 || bytes >= 1.8e19) return {};
  return static_cast<uint64_t>(bytes);
}

std::string formatMemorySize(uint64_t bytes) {
  const char* units[] = {"bytes", "kiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024 && unit < 4) {
    value /= 1024;
    ++unit;
  }
  char text[32];
  if (unit == 0) {
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  } else {
    std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, units[unit]);
  }
  return text;
}

}  // namespace prt
