#include "core/contained_call.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <cstring>
#include <thread>

namespace prt {
namespace {

using Cause = ContainedFailure::Cause;

ContainedFailure failureOf(const ContainedCall& call, ContainedLimits limits = {}) {
  try {
    runContained(call, limits, [](const std::exception&) { return 42; });
  } catch (const ContainedFailure& f) {
    return f;
  }
  return ContainedFailure(Cause::Threw, "(it returned)");
}

TEST(ContainedCallTest, ReturnsWhatTheCallMade) {
  std::vector<uint8_t> big(3 << 20);
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(i * 7);
  EXPECT_EQ(runContained([&] { return big; }, {}), big);  // larger than a pipe holds
  EXPECT_TRUE(runContained([] { return std::vector<uint8_t>{}; }, {}).empty());
}

TEST(ContainedCallTest, AnExceptionComesBackWithItsMessageAndLine) {
  const ContainedFailure f = failureOf([]() -> std::vector<uint8_t> {
    throw std::runtime_error("model.obj:3: not a number");
  });
  EXPECT_EQ(f.cause(), Cause::Threw);
  EXPECT_STREQ(f.what(), "model.obj:3: not a number");
  EXPECT_EQ(f.line(), 42);
}

// The crashes a library can have, for real: the parent lives on and names them.
TEST(ContainedCallTest, ACrashAnAbortOrAHangEndsTheChildNotTheCaller) {
  ContainedFailure f = failureOf([]() -> std::vector<uint8_t> {
    volatile int* nowhere = nullptr;
    *nowhere = 1;
    return {};
  });
  EXPECT_EQ(f.cause(), Cause::Crashed);
  EXPECT_NE(std::string(f.what()).find("SIGSEGV"), std::string::npos) << f.what();
  f = failureOf([]() -> std::vector<uint8_t> { std::abort(); });
  EXPECT_NE(std::string(f.what()).find("SIGABRT"), std::string::npos) << f.what();
  f = failureOf([]() -> std::vector<uint8_t> { ::_exit(9); });
  EXPECT_NE(std::string(f.what()).find("exit status 9"), std::string::npos) << f.what();
  f = failureOf(
      []() -> std::vector<uint8_t> {
        for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      },
      {0, 0.3, ""});
  EXPECT_EQ(f.cause(), Cause::TimedOut);
  EXPECT_NE(std::string(f.what()).find("took longer than"), std::string::npos);
}

TEST(ContainedCallTest, GrowingPastTheMemoryLimitIsOutOfMemory) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
  const ContainedFailure f = failureOf(
      []() -> std::vector<uint8_t> {
        std::vector<std::vector<uint8_t>> hoard;
        for (;;) hoard.emplace_back(size_t{64} << 20, 1);
      },
      {size_t{256} << 20, 60, "a test limit"});
  EXPECT_EQ(f.cause(), Cause::OutOfMemory);
  EXPECT_NE(std::string(f.what()).find("needs more than 256 MiB (a test limit)"), std::string::npos)
      << f.what();
}

}  // namespace
}  // namespace prt
