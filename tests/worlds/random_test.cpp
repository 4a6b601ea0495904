// The world's random streams (private to worlds/): reproducible, independent per robot and
// stream, and standard normal where sensors take their noise.
#include "random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace frob::worlds::detail {
namespace {

TEST(Rng, TheSameSeedRobotAndStreamGiveTheSameValues) {
  Rng a(7, 3, Stream::Sonar), b(7, 3, Stream::Sonar), other(7, 3, Stream::Odometry);
  int differ = 0;
  for (int k = 0; k < 1000; ++k) {
    const double x = a.gaussian();
    ASSERT_EQ(x, b.gaussian()) << "draw " << k;
    differ += x != other.gaussian();
  }
  EXPECT_EQ(differ, 1000);
}

TEST(Rng, GaussianIsStandardNormal) {
  // 10^6 draws: the mean's standard error is 0.001 and the variance's 0.0014, so 5 standard
  // errors are 0.005 and 0.007; the two-sided tail beyond 2 has probability 0.0455 (s.e. 0.0002).
  Rng rng(1, 0, Stream::Sonar);
  constexpr int n = 1'000'000;
  double sum = 0, squares = 0;
  int beyond2 = 0;
  for (int k = 0; k < n; ++k) {
    const double x = rng.gaussian();
    ASSERT_TRUE(std::isfinite(x));
    sum += x, squares += x * x;
    beyond2 += std::abs(x) > 2.0;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0.0, 0.005);
  EXPECT_NEAR(squares / n - mean * mean, 1.0, 0.007);
  EXPECT_NEAR(static_cast<double>(beyond2) / n, 0.0455, 0.001);
}

}  // namespace
}  // namespace frob::worlds::detail
