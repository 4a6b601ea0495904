#include "frob/behavior.hpp"

#include "frob/calculus.hpp"
#include "frob/sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <typeinfo>

namespace frob {
namespace {

using namespace literals;

TEST(Behavior, ConstantsLiftImplicitlyAndMixWithPlainValues) {
  Behavior<double> ten = 10;
  Behavior<double> b = ten * 2 + 1.5 - constant(0.5);
  EXPECT_EQ(sample(b, 0.1, 3), (std::vector<double>{21.0, 21.0, 21.0}));
  Behavior<bool> cmp = 3.0 < ten && !(ten == 11.0);
  EXPECT_TRUE(sample(cmp, 0.1, 1)[0]);
}

TEST(Behavior, TimeCountsFromTheFirstSample) {
  Behavior<double> t = time();
  EXPECT_EQ(sample(t, 0.25, 4), (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
}

TEST(Behavior, LiftAppliesAnyFunctionPointwise) {
  Behavior<double> t = time();
  auto b = lift([](double x, int k, double y) { return x * k + y; }, t, 3, t * t);
  std::vector<double> s = sample(b, 0.5, 3);
  EXPECT_EQ(s, (std::vector<double>{0.0, 1.75, 4.0}));
}

TEST(Behavior, VectorArithmeticStoresPlainVectors) {
  Behavior<Vec2> v = Vec2{1, 2};
  Behavior<Vec2> w = v * time() + Vec2{0, 1};  // an Eigen expression, evaluated into a Vec2
  std::vector<Vec2> s = sample(w, 1.0, 3);
  EXPECT_EQ(s[2], Vec2(2, 5));
  EXPECT_DOUBLE_EQ(sample(norm(Behavior<Vec2>(Vec2{3, 4})), 1.0, 1)[0], 5.0);
  EXPECT_DOUBLE_EQ(sample(distance(Behavior<Point2>(Point2{1, 1}), Point2{4, 5}), 1.0, 1)[0], 5.0);
}

TEST(Behavior, MathFunctionsArePointwise) {
  Behavior<double> t = time();
  std::vector<double> s = sample(sin(t) + abs(-t) + max(t, 0.5) + min(t, 0.5) + clamp(t, 0.2, 0.4), 0.5, 3);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[0], 0.0 + 0.0 + 0.5 + 0.0 + 0.2);
  EXPECT_DOUBLE_EQ(s[2], std::sin(1.0) + 1.0 + 1.0 + 0.5 + 0.4);
  EXPECT_DOUBLE_EQ(sample(atan2(constant(1.0), 1.0), 1.0, 1)[0], pi / 4);
  EXPECT_DOUBLE_EQ(sample(wrapAngle(constant(3 * pi / 2)), 1.0, 1)[0], wrapAngle(3 * pi / 2));
}

// time(), counting its evaluations in `evaluations`.
Behavior<double> countedTime(int& evaluations) {
  return lift(
      [&evaluations](double t) {
        ++evaluations;
        return t;
      },
      time());
}

TEST(Behavior, GlitchFreedomEvaluatesASharedNodeOncePerInstant) {
  int evaluations = 0;
  Behavior<double> counted = countedTime(evaluations);
  Behavior<double> diamond = counted + counted;  // two paths to one node
  Behavior<double> deeper = diamond * counted - counted;
  std::vector<double> s = sample(deeper, 1.0, 5);
  EXPECT_EQ(evaluations, 5);  // once per instant, not once per use
  EXPECT_DOUBLE_EQ(s[3], (3.0 + 3.0) * 3.0 - 3.0);
}

// Pointwise nodes and integrals bring their inputs up to date in one pass (a plan); a node shared by
// two graphs sampled in either order, or sampled on its own, is still evaluated once per instant.
TEST(Behavior, ANodeSharedBetweenGraphsIsEvaluatedOncePerInstant) {
  int evaluations = 0;
  Behavior<double> counted = countedTime(evaluations);
  Behavior<double> area = integral(counted);
  Behavior<double> a = area + counted * 2.0;
  Behavior<double> b = area - counted;
  Clock clock(0.5);
  for (int k = 0; k < 4; ++k) {
    const Instant& now = k == 0 ? clock.now() : clock.advance();
    double t = now.time;
    if (k % 2 == 0) {
      EXPECT_DOUBLE_EQ(a.at(now), t * t / 2 + 2 * t);
      EXPECT_DOUBLE_EQ(b.at(now), t * t / 2 - t);
    } else {
      EXPECT_DOUBLE_EQ(counted.at(now), t);
      EXPECT_DOUBLE_EQ(b.at(now), t * t / 2 - t);
      EXPECT_DOUBLE_EQ(a.at(now), t * t / 2 + 2 * t);
    }
    EXPECT_EQ(evaluations, k + 1);
  }
}

// A node that only `inner`'s graph owns is refreshed in its plan without a memo check; `outer`,
// which reads it through `inner` (shared: the test holds it), still finds it up to date.
TEST(Behavior, ANodeOnlyOneGraphOwnsIsEvaluatedOncePerInstantWhenAnotherReadsItThroughThatGraph) {
  int evaluations = 0;
  Behavior<double> inner = integral(countedTime(evaluations)) + 1.0;
  Behavior<double> outer = inner * 2.0;
  Clock clock(0.5);
  for (int k = 0; k < 4; ++k) {
    const Instant& now = k == 0 ? clock.now() : clock.advance();
    double area = now.time * now.time / 2;
    if (k % 2 == 0) {
      EXPECT_DOUBLE_EQ(inner.at(now), area + 1.0);
      EXPECT_DOUBLE_EQ(outer.at(now), 2 * (area + 1.0));
    } else {
      EXPECT_DOUBLE_EQ(outer.at(now), 2 * (area + 1.0));
      EXPECT_DOUBLE_EQ(inner.at(now), area + 1.0);
    }
    EXPECT_EQ(evaluations, k + 1);
  }
}

// A plan checks the memo of the nodes other graphs can reach (`shared`, and `time()` through it),
// and refreshes the ones only its own graph reaches unchecked.
TEST(Behavior, APlanChecksOnlyTheNodesOtherGraphsCanReach) {
  Behavior<double> shared = time() * 2.0;
  Behavior<double> root = [&] {
    Behavior<double> own = shared + 1.0;
    return Behavior<double>(own * own);
  }();
  std::vector<detail::PlanStep> plan = detail::planFor(*root.node());
  ASSERT_EQ(plan.size(), 4u);  // time(), shared, own, the end
  EXPECT_EQ(plan[0].run, plan[0].node->planStep(true));
  EXPECT_EQ(plan[1].run, plan[1].node->planStep(true));
  EXPECT_EQ(plan[2].run, plan[2].node->planStep(false));
  EXPECT_EQ(plan[3].node, nullptr);
}

// A plan of many steps, each running the next by a tail call, runs whole and in order.
TEST(Behavior, ALongPlanRunsEveryStep) {
  Behavior<double> t = time();
  Behavior<double> sum = t;
  for (int i = 0; i < 1000; ++i) sum = sum + 1.0;
  EXPECT_EQ(sample(sum, 0.5, 3), (std::vector<double>{1000.0, 1000.5, 1001.0}));
}

// Nodes that only their graph reaches (refreshed unchecked) give bit-identical values to the same
// nodes with handles held on them elsewhere (refreshed checked).
TEST(Behavior, NodesOnlyTheirGraphReachesGiveTheSameValuesAsSharedOnes) {
  auto build = [](std::vector<Behavior<double>>& keep) {
    Behavior<double> t = time();
    Behavior<double> wave = sin(t * 3.7) + 0.1 * t;
    Behavior<double> area = integral(wave);
    Behavior<double> slope = derivative(wave);
    keep = {t, wave, area, slope};
    return Behavior<double>(area * slope + wave / (1.0 + area * area));
  };
  std::vector<Behavior<double>> handles;
  Behavior<double> own = build(handles);
  handles.clear();
  Behavior<double> shared = build(handles);
  std::vector<double> a = sample(own, 0.01, 1000);
  std::vector<double> b = sample(shared, 0.01, 1000);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

// An exception that cuts a plan short, in a node of the plan or in its root, leaves the nodes it
// brought up to date as they are: sampled again at the same instant, none is evaluated twice.
TEST(Behavior, AnExceptionThatCutsAPlanShortLeavesNoNodeToBeEvaluatedTwice) {
  for (bool inRoot : {false, true}) {
    int evaluations = 0;
    bool fail = true;
    Behavior<double> b = [&] {
      Behavior<double> area = integral(countedTime(evaluations));
      auto failing = [&fail](double a) {
        if (fail) throw std::runtime_error("cut short");
        return a;
      };
      return inRoot ? Behavior<double>(lift(failing, area)) : Behavior<double>(lift(failing, area)) + 1.0;
    }();
    Clock clock(0.5);
    EXPECT_THROW(b.at(clock.now()), std::runtime_error);
    fail = false;
    EXPECT_DOUBLE_EQ(b.at(clock.now()), inRoot ? 0.0 : 1.0);
    EXPECT_EQ(evaluations, 1);
    EXPECT_DOUBLE_EQ(b.at(clock.advance()), inRoot ? 0.125 : 1.125);
    EXPECT_EQ(evaluations, 2);
  }
}

TEST(Behavior, RepeatedRunsAreBitIdentical) {
  auto build = [] {
    Behavior<double> t = time();
    return sin(t * 3.7) * exp(-t) + sqrt(t + 1.0) / (1.0 + t * t);
  };
  std::vector<double> a = sample(build(), 0.01, 1000);
  std::vector<double> b = sample(build(), 0.01, 1000);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  // And both are what the same arithmetic in plain C++ gives, bit for bit (-ffp-contract=off), so
  // that a wrong but repeatable graph fails too. Sample k is at t = k * 0.01, as Clock computes it.
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double t = static_cast<double>(k) * 0.01;
    const double expected = std::sin(t * 3.7) * std::exp(-t) + std::sqrt(t + 1.0) / (1.0 + t * t);
    ASSERT_EQ(std::memcmp(&a[k], &expected, sizeof(double)), 0) << "sample " << k << ": " << a[k] << " vs " << expected;
  }
}

TEST(Behavior, ThePapersRerrorReadsLikeThePaper) {
  // rerror r = limit (velocity r * sin thetamax) (setpoint - leftSonar r)
  //   where limit m v = (-m) `max` v `min` m
  auto limit = [](const Behavior<double>& m, const Behavior<double>& v) { return min(max(-m, v), m); };
  Behavior<double> velocity = 0.5;
  Behavior<double> left = 1.0 - time();  // the wall comes closer
  double setpoint = 0.6;
  double thetamax = 30_deg;
  Behavior<double> rerror = limit(velocity * std::sin(thetamax), setpoint - left);
  std::vector<double> s = sample(rerror, 0.1, 11);
  EXPECT_DOUBLE_EQ(s[0], -0.25);        // far from the wall: clipped at -m
  EXPECT_NEAR(s[4], 0.6 - 0.6, 1e-12);  // at the setpoint
  EXPECT_DOUBLE_EQ(s[10], 0.25);        // too close: clipped at +m
}

// Issue 15: the nearest of five sonars was min(min(min(...))) in four examples.
TEST(Behavior, MinAndMaxTakeAnyNumberOfBehaviorsAndValues) {
  Behavior<double> t = time();
  auto lo = min(t + 3.0, 2.5, t * 10.0, constant(4.0));
  auto hi = max(t, 0.25, 1.0 - t);
  EXPECT_EQ(sample(lo, 0.1, 4), (std::vector<double>{0.0, 1.0, 2.0, 2.5}));
  std::vector<double> h = sample(hi, 0.5, 3);  // t = 0, 0.5, 1
  EXPECT_EQ(h, (std::vector<double>{1.0, 0.5, 1.0}));
}

// Of equal values the first is chosen, as std::min and std::max of a list choose: -0.0 and 0.0
// compare equal, and the sign shows which one was taken.
TEST(Behavior, MinAndMaxOfManyChooseTheFirstOfEquals) {
  Behavior<double> zero = constant(0.0), negativeZero = constant(-0.0);
  EXPECT_TRUE(std::signbit(sample(min(negativeZero, zero, 1.0), 1.0, 1)[0]));
  EXPECT_FALSE(std::signbit(sample(min(zero, negativeZero, 1.0), 1.0, 1)[0]));
  EXPECT_TRUE(std::signbit(sample(max(negativeZero, zero, -1.0), 1.0, 1)[0]));
  EXPECT_FALSE(std::signbit(sample(max(zero, negativeZero, -1.0), 1.0, 1)[0]));
}

// Issue 29: expressions of numbers, truths and points are plain behaviors, each operator one node
// made by a function compiled once in libfrob, so that a controller compiles no nested expression
// types; a lifted function is one node type per signature, whatever the lambda.
TEST(Behavior, ExpressionsOfNumbersTruthsAndPointsAreBehaviorsNotExpressionTypes) {
  Behavior<double> t = time();
  Behavior<Point2> p = lift([](double x) { return Point2(x, 2 * x); }, t);
  static_assert(std::is_same_v<decltype(t * 2 + 1.0), Behavior<double>>);
  static_assert(std::is_same_v<decltype(t < 1.0 && !(t > 3)), Behavior<bool>>);
  static_assert(std::is_same_v<decltype(clamp(t, 0, 1.0) + min(t, 2.0, 3.0) + atan2(t, 1.0)), Behavior<double>>);
  static_assert(std::is_same_v<decltype(p - Point2(1, 1)), Behavior<Point2>>);
  static_assert(std::is_same_v<decltype(distance(p, Point2(0, 0)) + heading(p - p)), Behavior<double>>);
  Behavior<double> a = lift([](double x) { return x + 1; }, t), b = lift([](double x) { return x * 3; }, t);
  const auto typeOf = [](const Behavior<double>& x) -> const std::type_info& {
    const detail::NodeBase& node = *x.node();
    return typeid(node);
  };
  EXPECT_EQ(typeOf(a), typeOf(b));
  EXPECT_EQ(typeOf(t + 1.0), typeOf(t * 2.0));
  EXPECT_EQ(sample(t * 2 + 1.0, 1.0, 3), (std::vector<double>{1.0, 3.0, 5.0}));
  EXPECT_EQ(sample(distance(p, Point2(0, 0)), 1.0, 2)[1], std::sqrt(5.0));
  EXPECT_EQ(sample(lift([](bool x) { return x ? 1.0 : 0.0; }, t < 1.0 || t > 1.5), 1.0, 3), (std::vector<double>{1.0, 0.0, 1.0}));
}

struct Wall {
  double distance = 0;
  double angle = 0;
};

// Issue 15: a field of a behavior of a struct, without a lambda.
TEST(Behavior, MapTakesAFunctionOrAMemberPointer) {
  Behavior<Wall> wall = lift([](double t) { return Wall{1.0 + t, -t}; }, time());
  Behavior<double> d = wall.map(&Wall::distance);
  EXPECT_EQ(sample(d, 0.5, 2), (std::vector<double>{1.0, 1.5}));
  EXPECT_EQ(sample(wall.map([](const Wall& w) { return w.angle * 2; }), 0.5, 2), (std::vector<double>{0.0, -1.0}));
  EXPECT_EQ(sample((time() + 1.0).map([](double x) { return x * x; }), 1.0, 2), (std::vector<double>{1.0, 4.0}));
}

}  // namespace
}  // namespace frob
