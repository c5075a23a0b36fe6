// The simulator's network model and worker speeds.

#include "sim/network_model.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/input_error.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

TEST(SimNetworkTest, ColourlessResultsCountTheBytesOfRealOnes) {
  TaskSet tasks = TaskSet::range(10, 100);
  tasks.append(TaskRun{500, 7, 3});
  const ResultsMsg real{tasks, std::vector<float>(3 * tasks.size(), 0.5f)};
  EXPECT_EQ(messageBytes(ResultsMsg{tasks, {}}), encode(real).size());
  EXPECT_EQ(messageBytes(real), encode(real).size());
  EXPECT_EQ(messageBytes(RequestMsg{}), encode(RequestMsg{}).size());
}

TEST(SimNetworkTest, UncontendedMessageTakesLatencyPlusTransmission) {
  NetworkModel net(2, NetworkOptions{50e-6, 125e6, 5e-6});
  const double reach = net.depart(0, 1250, 1.0);
  EXPECT_DOUBLE_EQ(reach, 1.0 + 50e-6);
  EXPECT_DOUBLE_EQ(net.arrive(kMaster, 1250, reach), 1.0 + 50e-6 + 10e-6);
}

TEST(SimNetworkTest, MessagesQueueOnASharedLink) {
  NetworkModel net(3, NetworkOptions{0, 1e6, 0});
  // Two workers send 1000 bytes (1 ms each) to the master at once: incast on its link.
  const double a = net.arrive(kMaster, 1000, net.depart(0, 1000, 0));
  const double b = net.arrive(kMaster, 1000, net.depart(1, 1000, 0));
  EXPECT_DOUBLE_EQ(a, 1e-3);
  EXPECT_DOUBLE_EQ(b, 2e-3);
  // The master sends two messages in a row: the second leaves when the first has.
  EXPECT_DOUBLE_EQ(net.depart(kMaster, 1000, 0), 0);
  EXPECT_DOUBLE_EQ(net.depart(kMaster, 1000, 0), 1e-3);
}

TEST(SimNetworkTest, BadOptionsAreInputErrors) {
  EXPECT_THROW(validateNetworkOptions({-1, 1, 0}), InputError);
  EXPECT_THROW(validateNetworkOptions({0, 0, 0}), InputError);
  EXPECT_THROW(validateNetworkOptions({0, 1, -1}), InputError);
  EXPECT_NO_THROW(validateNetworkOptions({}));
}

TEST(SimWorkerSpeedsTest, SlowShareIsExactAndSeeded) {
  const std::vector<double> a = slowShareSpeeds(100, 0.25, 4, 7);
  EXPECT_EQ(std::count(a.begin(), a.end(), 0.25), 25);
  EXPECT_EQ(std::count(a.begin(), a.end(), 1.0), 75);
  EXPECT_EQ(slowShareSpeeds(100, 0.25, 4, 7), a);
  EXPECT_NE(slowShareSpeeds(100, 0.25, 4, 8), a);
  EXPECT_THROW(slowShareSpeeds(4, 1.5, 2, 1), InputError);
  EXPECT_THROW(slowShareSpeeds(4, 0.5, 0.5, 1), InputError);
}

TEST(SimWorkerSpeedsTest, LognormalHasMedianOneAndIsSeeded) {
  std::vector<double> s = lognormalSpeeds(1001, 0.5, 3);
  EXPECT_EQ(lognormalSpeeds(1001, 0.5, 3), s);
  std::sort(s.begin(), s.end());
  EXPECT_NEAR(s[500], 1.0, 0.1);
  EXPECT_GT(s.front(), 0);
  EXPECT_EQ(lognormalSpeeds(5, 0, 3), std::vector<double>(5, 1.0));
  EXPECT_THROW(lognormalSpeeds(4, -1, 1), InputError);
}

TEST(SimWorkerSpeedsTest, ValidationNamesTheProblem) {
  EXPECT_THROW(validateWorkerSpeeds({1, 1}, 3), InputError);
  EXPECT_THROW(validateWorkerSpeeds({1, -1}, 2), InputError);
  EXPECT_NO_THROW(validateWorkerSpeeds({1, 0.5}, 2));
}

}  // namespace
}  // namespace prt
