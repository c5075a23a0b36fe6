#include "core/contained_call.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <new>

#include "core/byte_codec.h"
#include "core/memory_budget.h"

namespace prt {
namespace {

enum class Status : uint8_t { Done = 0, Threw = 1, OutOfMemory = 2 };

// The address space this process maps now (VmSize), in bytes; 0 if unknown.
uint64_t mappedBytes() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (f == nullptr) return 0;
  char line[256];
  unsigned long long kib = 0;
  while (std::fgets(line, sizeof line, f) != nullptr) {
    if (std::sscanf(line, "VmSize: %llu kB", &kib) == 1) break;
  }
  std::fclose(f);
  return static_cast<uint64_t>(kib) * 1024;
}

void writeAll(int fd, const uint8_t* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(3);
    data += n;
    size -= static_cast<size_t>(n);
  }
}

[[noreturn]] void childMain(int fd, const ContainedCall& call, uint64_t memoryBytes,
                            const LineOf& lineOf) {
  // What the library prints (assimp's assertion and parser messages) is not prt's output.
  if (const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC); null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::close(null);
  }
  if (const uint64_t mapped = mappedBytes(); mapped > 0) {
    const rlimit limit{mapped + memoryBytes, mapped + memoryBytes};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  ByteWriter out;
  try {
    const std::vector<uint8_t> bytes = call();
    const auto done = static_cast<uint8_t>(Status::Done);
    writeAll(fd, &done, 1);
    writeAll(fd, bytes.data(), bytes.size());
    ::close(fd);
    ::_exit(0);
  } catch (const std::bad_alloc&) {
    out.pod(static_cast<uint8_t>(Status::OutOfMemory));
  } catch (const std::exception& e) {
    out.out.clear();
    out.pod(static_cast<uint8_t>(Status::Threw));
    out.pod(static_cast<int32_t>(lineOf ? lineOf(e) : 0));
    out.text(std::string(e.what()).substr(0, 60000));
  }
  writeAll(fd, out.out.data(), out.out.size());
  ::close(fd);
  ::_exit(0);
}

std::string signalName(int sig) {
  const char* what = ::strsignal(sig);
  std::string name = sig == SIGSEGV   ? "SIGSEGV"
                     : sig == SIGABRT ? "SIGABRT"
                     : sig == SIGBUS  ? "SIGBUS"
                     : sig == SIGFPE  ? "SIGFPE"
                     : sig == SIGILL  ? "SIGILL"
                     : sig == SIGKILL ? "SIGKILL"
                                      : "signal " + std::to_string(sig);
  return what != nullptr ? name + " (" + what + ")" : name;
}

}  // namespace

std::vector<uint8_t> runContained(const ContainedCall& call, const ContainedLimits& limits,
                                  const LineOf& lineOf) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::bad_alloc();
  const uint64_t memory = limits.memoryBytes != 0 ? limits.memoryBytes : memoryBudgetBytes();
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::bad_alloc();  // fork fails for want of memory or of processes
  }
  if (child == 0) {
    ::close(fds[0]);
    childMain(fds[1], call, memory, lineOf);
  }
  ::close(fds[1]);
  std::vector<uint8_t> bytes;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  bool timedOut = false;
  uint8_t buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      timedOut = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
  ::close(fds[0]);
  if (timedOut) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  using Cause = ContainedFailure::Cause;
  if (timedOut) {
    throw ContainedFailure(Cause::TimedOut, "took longer than " +
                                                std::to_string(static_cast<long>(limits.seconds)) +
                                                " s and was stopped");
  }
  if (WIFSIGNALED(status)) {
    throw ContainedFailure(Cause::Crashed, "crashed: " + signalName(WTERMSIG(status)));
  }
  if (bytes.empty()) {
    throw ContainedFailure(Cause::Crashed, "ended without an answer (exit status " +
                                               std::to_string(WEXITSTATUS(status)) + ")");
  }
  const auto kind = static_cast<Status>(bytes[0]);
  if (kind == Status::Done) {
    bytes.erase(bytes.begin());
    return bytes;
  }
  if (kind == Status::OutOfMemory) {
    const std::string rule =
        limits.memoryRule.empty() ? "the memory budget; --max-memory sets it" : limits.memoryRule;
    throw ContainedFailure(Cause::OutOfMemory,
                           "needs more than " + formatMemorySize(memory) + " (" + rule + ")");
  }
  try {
    ByteReader r(bytes.data() + 1, bytes.size() - 1, "contained call");
    const auto line = r.pod<int32_t>();
    const std::string message = r.text();
    throw ContainedFailure(Cause::Threw, message, line);
  } catch (const ContainedFailure&) {
    throw;
  } catch (const std::exception&) {
    throw ContainedFailure(Cause::Crashed, "gave an answer that does not decode");
  }
}

}  // namespace prt
