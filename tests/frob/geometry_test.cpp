#include "frob/geometry.hpp"

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <cmath>

namespace frob {
namespace {

using namespace literals;

TEST(Geometry, UnitLiteralsAreSi) {
  EXPECT_DOUBLE_EQ(20_cm, 0.2);
  EXPECT_DOUBLE_EQ(1.5_m, 1.5);
  EXPECT_DOUBLE_EQ(250_ms, 0.25);
  EXPECT_DOUBLE_EQ(90_deg, pi / 2);
  EXPECT_DOUBLE_EQ(5_s, 5.0);
}

TEST(Geometry, WrapAngleLandsInHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrapAngle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(wrapAngle(pi), pi);
  EXPECT_DOUBLE_EQ(wrapAngle(-pi), pi);  // -pi maps to +pi: the interval is (-pi, pi]
  EXPECT_NEAR(wrapAngle(3 * pi / 2), -pi / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(-7 * pi / 2), pi / 2, 1e-14);
  EXPECT_NEAR(wrapAngle(4 * pi + 0.25), 0.25, 1e-14);
  EXPECT_EQ(wrapAngle(std::nextafter(-pi, 0.0)), std::nextafter(-pi, 0.0));  // inside: unchanged, to the bit
  EXPECT_EQ(wrapAngle(std::nextafter(pi, 4.0)), std::nextafter(pi, 4.0) - 2.0 * pi);
  EXPECT_TRUE(std::isnan(wrapAngle(std::nan(""))));
}

TEST(Geometry, AngleDiffTakesTheShortWayRound) {
  EXPECT_NEAR(angleDiff(170_deg, -170_deg), 20_deg, 1e-14);
  EXPECT_NEAR(angleDiff(-170_deg, 170_deg), -20_deg, 1e-14);
  EXPECT_NEAR(angleDiff(0, 90_deg), 90_deg, 1e-15);
  // geometry.hpp's examples: the sign is the way to turn, positive to the left.
  EXPECT_NEAR(angleDiff(pi / 2, 0), -pi / 2, 1e-15);
  EXPECT_NEAR(angleDiff(3, -3), 2 * pi - 6, 1e-14);
}

TEST(Geometry, VectorsAreEigen) {
  Point2 a{1, 2};
  Point2 b{4, 6};
  EXPECT_DOUBLE_EQ(distance(a, b), 5.0);
  EXPECT_NEAR(heading(unitVector(1.25)), 1.25, 1e-15);
  // An Eigen solve, to prove the dependency is linked and usable through frob::frob.
  Eigen::Matrix2d m;
  m << 2, 1, 1, 3;
  Eigen::Vector2d x = m.colPivHouseholderQr().solve(Eigen::Vector2d{3, 5});
  EXPECT_NEAR(x.x(), 0.8, 1e-12);
  EXPECT_NEAR(x.y(), 1.4, 1e-12);
}

}  // namespace
}  // namespace frob
