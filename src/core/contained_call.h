#pragma once
// runContained: a call made in a child process, so that a library that crashes, aborts,
// loops or allocates without bound on a user's file (assimp on some valid-looking files)
// ends the child, not prt. The child is a fork of this process: it runs `call` with its
// address space limited to what it already maps plus `memoryBytes`, returns the bytes `call`
// made through a pipe and ends with _exit (no destructors, no atexit handlers: an MPI rank's
// child never touches MPI). What the child prints goes to /dev/null. The parent waits at most `seconds`, then kills it.
//
// Outcomes: the bytes; or ContainedFailure — the child threw (its message, and the line a
// MeshFileError-like error carried), ran out of memory, took too long, or died of a signal
// (named: "SIGSEGV (segmentation fault)"). Call from one thread at a time per call; other
// threads of the parent are not copied into the child, so `call` must not wait for them.

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace prt {

struct ContainedLimits {
  uint64_t memoryBytes = 0;  // beyond what the process maps already; 0: the memory budget
  double seconds = 600;
  // Where memoryBytes comes from, for the message when the child needs more ("" with the
  // memory budget: "the memory budget; --max-memory sets it").
  std::string memoryRule;
};

class ContainedFailure : public std::runtime_error {
 public:
  enum class Cause { Threw, OutOfMemory, TimedOut, Crashed };
  ContainedFailure(Cause cause, const std::string& message, int line = 0)
      : std::runtime_error(message), cause_(cause), line_(line) {}
  Cause cause() const { return cause_; }
  int line() const { return line_; }  // as the child's exception gave it; 0: none

 private:
  Cause cause_;
  int line_;
};

// What `call` throws in the child: the message (e.what()) and a line number, which
// `lineOf` reads from the exception (0 when it has none).
using ContainedCall = std::function<std::vector<uint8_t>()>;
using LineOf = std::function<int(const std::exception&)>;

std::vector<uint8_t> runContained(const ContainedCall& call, const ContainedLimits& limits,
                                  const LineOf& lineOf = {});

}  // namespace prt
