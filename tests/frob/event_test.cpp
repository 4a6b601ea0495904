#include "frob/event.hpp"

#include "frob/errors.hpp"
#include "frob/sampling.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

std::vector<double> times(const std::vector<std::pair<double, Unit>>& occ) {
  std::vector<double> out;
  for (const auto& [t, u] : occ) out.push_back(t);
  return out;
}

TEST(Event, NeverNeverOccurs) { EXPECT_TRUE(occurrences(never<int>(), 0.1, 100).empty()); }

TEST(Event, PredicateFiresAtTheStartWhenTheConditionAlreadyHolds) {
  EXPECT_EQ(times(occurrences(predicate(constant(true)), 0.1, 10)), std::vector<double>{0.0});
}

TEST(Event, PredicateFiresAgainOnlyAfterTheConditionWasFalse) {
  // true on [0, 0.3), false on [0.3, 0.6), true again from 0.6.
  Behavior<double> t = time();
  Behavior<bool> c = t < 0.25 || t > 0.55;
  std::vector<double> t2 = times(occurrences(predicate(c), 0.1, 10));
  ASSERT_EQ(t2.size(), 2u);
  EXPECT_EQ(t2[0], 0.0);
  EXPECT_NEAR(t2[1], 0.6, 1e-12);
}

TEST(Event, PredicateCrossingIsWithinOneStepAtEveryRate) {
  // Sampling-rate independence: the crossing at t = 0.55 is found within one step at dt, dt/2, dt/4.
  for (double dt : {0.1, 0.05, 0.025}) {
    std::optional<double> t = firstOccurrence(predicate(time() > 0.55), dt, 1000);
    ASSERT_TRUE(t) << dt;
    EXPECT_GE(*t, 0.55) << dt;
    EXPECT_LE(*t, 0.55 + dt) << dt;
  }
}

TEST(Event, MapTransformsOccurrencesWithOrWithoutTheirValue) {
  Event<std::int64_t> ticks = every(0.5);
  auto doubled = occurrences(ticks.map([](std::int64_t k) { return 2 * k; }), 0.1, 12);
  ASSERT_EQ(doubled.size(), 2u);
  EXPECT_EQ(doubled[1].second, 4);
  auto names = occurrences(after(0.3).map([] { return std::string("go"); }), 0.1, 10);
  ASSERT_EQ(names.size(), 1u);
  EXPECT_EQ(names[0].second, "go");
}

TEST(Event, OnSimultaneousOccurrencesTheLeftEventWins) {
  Event<int> left = after(0.5).map([] { return 1; });
  Event<int> right = after(0.5).map([] { return 2; });
  Event<int> early = after(0.2).map([] { return 3; });
  auto occ = occurrences(left | right | early, 0.1, 10);
  ASSERT_EQ(occ.size(), 2u);
  EXPECT_EQ(occ[0].second, 3);
  EXPECT_DOUBLE_EQ(occ[1].first, 0.5);
  EXPECT_EQ(occ[1].second, 1);
}

// Decided (frob/README.md, "Cases the paper leaves open"): at an instant where both occur, `a | b`
// is a's occurrence alone (the paper: "taking the first one to occur"), so a filter after it sees
// only a's; filtering each side first keeps b's.
TEST(Event, AFilterAfterAnOrSeesOnlyTheWinnerOfATie) {
  auto a = [] { return after(0.3).as(1); };
  auto b = [] { return after(0.3).as(2); };
  auto isTwo = [](int v) { return v == 2; };
  EXPECT_TRUE(occurrences((a() | b()).filter(isTwo), 0.1, 5).empty());
  auto kept = occurrences(a().filter(isTwo) | b().filter(isTwo), 0.1, 5);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].second, 2);
}

TEST(Event, FilterAndOnce) {
  Event<std::int64_t> ticks = every(0.1);
  auto even = occurrences(ticks.filter([](std::int64_t k) { return k % 2 == 0; }), 0.1, 10);
  ASSERT_EQ(even.size(), 4u);  // k = 2, 4, 6, 8 at t = 0.2 ... 0.8; t = 0.9 gives k = 9
  EXPECT_EQ(even[3].second, 8);
  auto first = occurrences(once(every(0.2)), 0.1, 10);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_DOUBLE_EQ(first[0].first, 0.2);
}

TEST(Event, SnapshotPairsTheValueWithABehaviorAtThatInstant) {
  auto occ = occurrences(snapshot(every(0.3), time() * 10.0), 0.1, 10);
  ASSERT_EQ(occ.size(), 3u);
  EXPECT_EQ(occ[1].second.first, 2);
  EXPECT_NEAR(occ[1].second.second, 6.0, 1e-12);
}

TEST(Event, TimersCountFromTheirOwnStart) {
  auto occ = occurrences(every(0.25), 0.05, 21);
  std::vector<double> t;
  for (auto& [when, k] : occ) t.push_back(when);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(t[0], 0.25, 1e-12);
  EXPECT_NEAR(t[3], 1.0, 1e-12);
  EXPECT_EQ(occurrences(after(1.0), 0.1, 100).size(), 1u);
  EXPECT_NEAR(occurrences(after(1.0), 0.1, 100)[0].first, 1.0, 1e-12);
}

// Issue 15: a period shorter than the step is not slowed down to one count per step: each
// occurrence carries every period elapsed, so the count at a time is the same at any rate.
TEST(Event, EveryShorterThanTheStepCountsEveryPeriod) {
  std::vector<std::pair<double, std::int64_t>> occ = occurrences(every(0.03), 0.1, 5);
  ASSERT_EQ(occ.size(), 4u);  // one per step after the start
  std::vector<std::int64_t> counts;
  for (const auto& [t, k] : occ) counts.push_back(k);
  // floor(t / 0.03) at t = 0.1, 0.2, 0.3 and 0.4 (0.3 is exactly 10 periods, within rounding).
  EXPECT_EQ(counts, (std::vector<std::int64_t>{3, 6, 10, 13}));
  // Longer periods still count 1, 2, 3 at the first step at or after each.
  std::vector<std::pair<double, std::int64_t>> slow = occurrences(every(0.25), 0.1, 10);
  ASSERT_EQ(slow.size(), 3u);
  EXPECT_NEAR(slow[0].first, 0.3, 1e-12);
  EXPECT_EQ(slow[2].second, 3);
}

TEST(Event, TimersRefuseAPeriodThatIsNotPositive) {
  EXPECT_THROW((void)every(0.0), UsageError);
  EXPECT_THROW((void)after(-1.0), UsageError);
  EXPECT_EQ(occurrences(after(0.0), 0.1, 3).size(), 1u);  // at once, at its first sample
}

// Issue 15: an event with a value of its own, without `.map([] { return v; })`.
TEST(Event, AsReplacesEachOccurrencesValue) {
  auto occ = occurrences(every(0.2).as(std::string("tick")), 0.1, 5);
  ASSERT_EQ(occ.size(), 2u);
  EXPECT_EQ(occ[0].second, "tick");
  EXPECT_NEAR(occ[1].first, 0.4, 1e-12);
}

}  // namespace
}  // namespace frob
