#include "frob/calculus.hpp"

#include "frob/sampling.hpp"
#include "frob/switching.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace frob {
namespace {

TEST(Calculus, IntegralOfAConstantIsExact) {
  std::vector<double> s = sample(integral(constant(2.0)), 0.1, 11);
  EXPECT_EQ(s[0], 0.0);
  EXPECT_NEAR(s[10], 2.0, 1e-12);
}

TEST(Calculus, IntegralConvergesToTheClosedFormAsTheStepShrinks) {
  // integral of sin over [0, 2] is 1 - cos 2. The trapezoidal rule's error shrinks with dt^2,
  // so halving the step must cut the error about four times.
  double exact = 1.0 - std::cos(2.0);
  std::vector<double> errors;
  for (double dt : {0.1, 0.05, 0.025}) {
    std::int64_t steps = std::llround(2.0 / dt) + 1;
    errors.push_back(std::abs(sample(integral(sin(time())), dt, steps).back() - exact));
  }
  EXPECT_LT(errors[0], 2e-3);
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.1);
  EXPECT_NEAR(errors[1] / errors[2], 4.0, 0.1);
}

TEST(Calculus, IntegralOfAVector) {
  std::vector<Vec2> s = sample(integral(Behavior<Vec2>(Vec2{1.0, -2.0})), 0.5, 5);
  EXPECT_NEAR(s[4].x(), 2.0, 1e-12);
  EXPECT_NEAR(s[4].y(), -4.0, 1e-12);
}

// Decided (frob/README.md, "Cases the paper leaves open"): a derivative reads 0 at its first
// sample, as though its behavior had held its first value since its start (as integral takes it).
TEST(Calculus, DerivativeIsZeroAtTheStartThenTheBackwardDifference) {
  Behavior<double> t = time();
  std::vector<double> s = sample(derivative(t * t), 0.01, 101);
  EXPECT_EQ(s[0], 0.0);
  EXPECT_NEAR(s[100], 2.0, 0.01);  // backward difference: 2t - dt at t = 1
  std::vector<Vec2> v = sample(derivative(Behavior<Vec2>(Vec2{1, 1}) * time()), 0.1, 3);
  EXPECT_NEAR(v[2].x(), 1.0, 1e-12);
}

TEST(Calculus, AtMinGivesTheValueWhereTheKeyWasSmallest) {
  Behavior<double> t = time();
  Behavior<double> key = (t - 1.2) * (t - 1.2);  // smallest at t = 1.2
  std::vector<double> s = sample(atMin(key, t * 10.0), 0.1, 31);
  EXPECT_NEAR(s[5], 5.0, 1e-12);   // still falling: the minimum so far is now
  EXPECT_NEAR(s[30], 12.0, 1e-9);  // after the minimum, its value stays
  std::vector<double> m = sample(atMax(-key, t), 0.1, 31);
  EXPECT_NEAR(m[30], 1.2, 1e-9);
}

TEST(Calculus, StatefulBehaviorsStartWhenSwitchedIn) {
  // derivative and atMin created inside untilB's new behavior begin at the switch.
  Behavior<double> b = untilB(constant(-1.0), after(1.0).map([] {
    Behavior<double> t = time();
    return derivative(t) + atMin(t, t);
  }));
  std::vector<double> s = sample(b, 0.1, 13);
  EXPECT_EQ(s[10], 0.0);          // both start at the switch: derivative 0, atMin(t, t) = 0
  EXPECT_NEAR(s[12], 1.0, 1e-9);  // derivative of local time is 1; atMin stays 0
}

}  // namespace
}  // namespace frob
