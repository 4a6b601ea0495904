// Which cores a run's hosts are given: all the allowed ones but the grader's, only when the hosts
// and the grader cannot have one each.
#include "host_cores.hpp"

#include "frob/run/run_cores.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <initializer_list>
#include <thread>

namespace frob::course {
namespace {

cpu_set_t cores(std::initializer_list<int> list) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (const int c : list) CPU_SET(c, &set);
  return set;
}

void expectCores(const std::optional<cpu_set_t>& got, std::initializer_list<int> want) {
  ASSERT_TRUE(got.has_value());
  const cpu_set_t expected = cores(want);
  EXPECT_TRUE(CPU_EQUAL(&*got, &expected)) << CPU_COUNT(&*got) << " cores";
}

TEST(HostCores, HostsThatCannotHaveACoreEachGetEveryCoreButTheGraders) {
  expectCores(hostCores(cores({0, 1}), 0, 4), {1});
  expectCores(hostCores(cores({0, 1}), 1, 2), {0});
  expectCores(hostCores(cores({2, 3, 5}), 3, 3), {2, 5});
  expectCores(hostCores(cores({0, 1, 2, 3}), 2, 4), {0, 1, 3});
}

TEST(HostCores, NoPlacementWhenEachHasACoreOrNoneIsLeft) {
  EXPECT_FALSE(hostCores(cores({0, 1}), 0, 1));           // a host and the grader: a core each
  EXPECT_FALSE(hostCores(cores({0, 1, 2, 3, 4}), 0, 4));  // four hosts and the grader
  EXPECT_FALSE(hostCores(cores({0}), 0, 4));              // one core: nothing to keep
  EXPECT_FALSE(hostCores(cores({0, 1}), 2, 4));           // the grader on a core it may not use (moved since)
  EXPECT_FALSE(hostCores(cores({0, 1}), -1, 4));          // sched_getcpu failed
}

// A class's runs take a core each: never one another holds, the taker runs on it alone, and has its
// cores back after. More takers than cores wait their turn.
TEST(RunCores, EachRunHoldsACoreNoOtherRunHolds) {
  RunCores cores;
  cpu_set_t allowed;
  ASSERT_EQ(::sched_getaffinity(0, sizeof allowed, &allowed), 0);
  EXPECT_EQ(cores.size(), static_cast<std::size_t>(CPU_COUNT(&allowed)));
  std::array<std::atomic<int>, CPU_SETSIZE> holders{};
  std::atomic<int> shared{0}, misplaced{0}, unrestored{0};
  const auto run = [&] {
    cpu_set_t mine;
    ::sched_getaffinity(0, sizeof mine, &mine);
    for (int k = 0; k < 200; ++k) {
      {
        const RunCores::Held held = cores.take();
        if (holders[held.core()]++ != 0) ++shared;
        cpu_set_t now;
        ::sched_getaffinity(0, sizeof now, &now);
        if (CPU_COUNT(&now) != 1 || !CPU_ISSET(held.core(), &now)) ++misplaced;
        --holders[held.core()];
      }
      cpu_set_t after;
      ::sched_getaffinity(0, sizeof after, &after);
      if (!CPU_EQUAL(&after, &mine)) ++unrestored;
    }
  };
  std::vector<std::thread> runs;
  for (std::size_t t = 0; t < cores.size() + 2; ++t) runs.emplace_back(run);
  for (std::thread& t : runs) t.join();
  EXPECT_EQ(shared, 0);
  EXPECT_EQ(misplaced, 0);
  EXPECT_EQ(unrestored, 0);
}

TEST(RunCores, TheCoresGivenAreTheOnesHandedOut) {
  RunCores cores({3});
  EXPECT_EQ(cores.size(), 1u);
  RunCores::Held held = cores.take();
  EXPECT_EQ(held.core(), 3);
  RunCores::Held moved = std::move(held);
  EXPECT_EQ(held.core(), -1);
  EXPECT_EQ(moved.core(), 3);
}

}  // namespace
}  // namespace frob::course
