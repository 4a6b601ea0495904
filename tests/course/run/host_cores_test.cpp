// Which cores a run's hosts are given: all the allowed ones but the grader's, only when the hosts
// and the grader cannot have one each.
#include "host_cores.hpp"

#include <gtest/gtest.h>

#include <initializer_list>

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

}  // namespace
}  // namespace frob::course
