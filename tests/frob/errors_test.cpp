#include "frob/errors.hpp"

#include "frob/sampling.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace frob {
namespace {

TEST(Errors, CheckFiniteNamesTheBehaviorAndTheTime) {
  Behavior<double> t = time();
  Behavior<double> b = checkFinite(log(0.35 - t), "turn rate");  // NaN from t = 0.4 on
  try {
    (void)sample(b, 0.1, 10);
    FAIL() << "a NaN went unnoticed";
  } catch (const FrobError& e) {
    EXPECT_NE(std::string(e.what()).find("turn rate"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("t = 0.400"), std::string::npos) << e.what();
  }
}

TEST(Errors, IsFiniteCoversTheRobotTypes) {
  double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(isFinite(Wheels{1, 2}));
  EXPECT_FALSE(isFinite(Wheels{nan, 0}));
  EXPECT_FALSE(isFinite(Vec2{0, std::numeric_limits<double>::infinity()}));
  EXPECT_FALSE(isFinite(Pose2{Point2{0, 0}, nan}));
}

TEST(Errors, FrobAssertThrowsUsageErrorWithTheMessage) {
  try {
    FROB_ASSERT(1 + 1 == 3, "arithmetic is broken");
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("arithmetic is broken"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("errors_test.cpp"), std::string::npos);
  }
}

}  // namespace
}  // namespace frob
