#include "core/exit_status.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace prt {

namespace {

// PRT_STATUS_FILE with `suffix`, on rank 0 only; "" elsewhere or when it is not set.
std::string statusPath(const char* suffix) {
  const char* path = std::getenv("PRT_STATUS_FILE");
  if (path == nullptr || *path == '\0') return "";
  for (const char* rank : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    const char* value = std::getenv(rank);
    if (value != nullptr && std::strcmp(value, "0") != 0) return "";  // rank 0 speaks
  }
  return std::string(path) + suffix;
}

void writeText(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;  // the launcher then reports that nothing came
  const ssize_t written = ::write(fd, text.data(), text.size());
  (void)written;
  ::close(fd);
}

}  // namespace

void recordExitStatus(int code) {
  static std::atomic<bool> recorded{false};
  const std::string path = statusPath("");
  if (path.empty() || recorded.exchange(true)) return;
  writeText(path, std::to_string(code) + "\n");
}

void recordCheckpointPath(const std::string& checkpoint) {
  const std::string path = statusPath(".resume");
  if (path.empty() || checkpoint.empty()) return;
  writeText(path, checkpoint + "\n");
}

}  // namespace prt
