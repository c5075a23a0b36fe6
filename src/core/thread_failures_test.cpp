#include "core/thread_failures.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

namespace prt {
namespace {

TEST(ThreadFailures, KeepsTheFirstExceptionOfAnyThreadForTheStarterToRethrow) {
  ThreadFailures failures;
  EXPECT_FALSE(failures.any());
  EXPECT_NO_THROW(failures.rethrowFirst());
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) {
    threads.emplace_back([&, i] {
      // Without run(), the bad_alloc would end the process (std::terminate).
      failures.run([i] {
        if (i == 2) throw std::bad_alloc();
      });
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_TRUE(failures.any());
  EXPECT_THROW(failures.rethrowFirst(), std::bad_alloc);
}

TEST(ThreadFailures, RunSaysWhetherTheBodyThrewAndKeepsOnlyTheFirst) {
  ThreadFailures failures;
  EXPECT_TRUE(failures.run([] {}));
  EXPECT_FALSE(failures.run([] { throw std::runtime_error("first"); }));
  EXPECT_FALSE(failures.run([] { throw std::bad_alloc(); }));
  try {
    failures.rethrowFirst();
    ADD_FAILURE() << "nothing rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "first");
  }
}

}  // namespace
}  // namespace prt
