#include "frob/switching.hpp"

#include "frob/calculus.hpp"
#include "frob/errors.hpp"
#include "frob/sampling.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

TEST(Switching, UntilBSwitchesAtTheEventAndStartsTheNewBehaviorThere) {
  // time() inside the new behavior counts from the switch, not from the program's start.
  Behavior<double> b = untilB(constant(-1.0), after(0.3).map([] { return time(); }));
  std::vector<double> s = sample(b, 0.1, 6);
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(s[2], -1.0);
  EXPECT_EQ(s[3], 0.0);  // switched at t = 0.3, in the same instant
  EXPECT_NEAR(s[5], 0.2, 1e-12);
}

// The switch starts the new behavior at the event's instant, which may fall between samples:
// after(0.25) is sampled at 0.3 s, and the time() switched in there reads 0.05 s.
TEST(Switching, UntilBStartsTheNewBehaviorAtTheEventsInstantBetweenSamples) {
  Behavior<double> b = untilB(constant(-1.0), after(0.25).map([] { return time(); }));
  std::vector<double> s = sample(b, 0.1, 5);
  EXPECT_EQ(s[2], -1.0);
  EXPECT_NEAR(s[3], 0.05, 1e-12);
  EXPECT_NEAR(s[4], 0.15, 1e-12);
}

TEST(Switching, AnIntegralSwitchedInStartsAtTheSwitch) {
  // Built before the switch, but first sampled at t = 2: it integrates from there.
  Behavior<double> rate = 1.0;
  Behavior<double> area = integral(rate);
  Behavior<double> b = untilB(constant(0.0), after(2.0).map([area] { return area; }));
  std::vector<double> s = sample(b, 0.01, 301);
  EXPECT_NEAR(s[300], 1.0, 1e-9);  // integral of 1 over [2, 3]
}

TEST(Switching, SwitcherFollowsEveryOccurrence) {
  Behavior<double> b = switcher(constant(0.0), every(0.2).map([](std::int64_t k) { return constant(double(k)); }));
  std::vector<double> s = sample(b, 0.1, 7);
  EXPECT_EQ(s, (std::vector<double>{0, 0, 1, 1, 2, 2, 3}));
}

TEST(Switching, HoldKeepsTheLatestValue) {
  Behavior<std::int64_t> b = hold(std::int64_t{-1}, every(0.2));
  EXPECT_EQ(sample(b, 0.1, 5), (std::vector<std::int64_t>{-1, -1, 1, 1, 2}));
}

// Switches to a fresh copy of itself every 0.1 s, forever.
Behavior<double> sawtooth() {
  return untilB(integral(constant(1.0)), after(0.1).map([] { return sawtooth(); }));
}

TEST(Switching, ABehaviorThatSwitchesForeverRunsInBoundedMemory) {
  long before = liveNodeCount();
  Behavior<double> b = sawtooth();
  Clock clock(0.01);
  long most = 0;
  double last = 0.0;
  for (int i = 0; i < 1'000'000; ++i) {
    last = b.at(i == 0 ? clock.now() : clock.advance());
    if (i % 1000 == 0) most = std::max(most, liveNodeCount() - before);
  }
  // One sawtooth is a switch, an integral, a constant, a timer and its map: a handful of nodes.
  // Without freeing, 10^6 steps would leave 10^4 generations alive.
  EXPECT_LE(most, 20);
  EXPECT_GE(last, 0.0);
  EXPECT_LE(last, 0.1 + 1e-9);
}

// Switches to a copy of itself whose event occurs at once: an endless chain within one instant.
Behavior<double> runaway() {
  return untilB(constant(0.0), predicate(constant(true)).map([] { return runaway(); }));
}

TEST(Switching, AnEndlessSwitchChainAtOneInstantIsReportedNotAStackOverflow) {
  Behavior<double> b = runaway();
  Clock clock(0.01);
  try {
    (void)b.at(clock.now());
    FAIL() << "the runaway switch went unnoticed";
  } catch (const FrobError& e) {
    EXPECT_NE(std::string(e.what()).find("switched more than 1000 times at one instant"), std::string::npos) << e.what();
  }
  // A finite chain at one instant is fine: three switches, then a value.
  Behavior<double> chain =
      untilB(constant(0.0),
             predicate(constant(true)).map([] { return untilB(constant(1.0), predicate(constant(true)).map([] { return constant(2.0); })); }));
  EXPECT_EQ(chain.at(clock.advance()), 2.0);
}

}  // namespace
}  // namespace frob
