#pragma once
// startThread: every thread the program starts is started here. A thread the system cannot
// create — its stack counts against ulimit -v, and the process may be at its thread limit —
// throws std::system_error from std::thread's constructor; here that becomes std::bad_alloc,
// which every driver already carries to main() and reports as "prt: error: out of memory ..."
// (thread_failures.h), whichever thread asked. Other errors pass unchanged.

#include <new>
#include <system_error>
#include <thread>
#include <utility>

namespace prt {

template <typename Fn, typename... Args>
std::thread startThread(Fn&& fn, Args&&... args) {
  try {
    return std::thread(std::forward<Fn>(fn), std::forward<Args>(args)...);
  } catch (const std::system_error& e) {
    if (e.code() == std::errc::resource_unavailable_try_again ||
        e.code() == std::errc::not_enough_memory) {
      throw std::bad_alloc();
    }
    throw;
  }
}

}  // namespace prt
