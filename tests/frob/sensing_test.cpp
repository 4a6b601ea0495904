#include "frob/sensing.hpp"

#include "frob/errors.hpp"
#include "frob/sampling.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

using namespace literals;

// Sonar i reads 3 + i metres, except those the test sets nearer.
Robot ringWith(std::function<double(int)> near) {
  return Robot(nomadSpec(), ScriptedSensors{.sonar = [near](double, int i) { return near(i); }});
}

TEST(Sensing, NearestEchoIsTheSmallestRangeInTheSpanWithItsDirection) {
  // Sonars 2, 3 and 4 (45, 67.5, 90 deg) read 1.2, 0.8, 0.9; sonar 8 (behind) reads 0.1.
  Robot r = ringWith([](int i) { return i == 2 ? 1.2 : i == 3 ? 0.8 : i == 4 ? 0.9 : i == 8 ? 0.1 : 3.0 + i; });
  Echo left = sample(nearestEcho(r, 45_deg, 135_deg), 0.1, 1)[0];
  EXPECT_EQ(left.range, 0.8);
  EXPECT_NEAR(left.angle, 67.5_deg, 1e-12);
  // A span across the front (-30 to 30 deg) holds sonars 15, 0 and 1.
  Echo ahead = sample(nearestEcho(r, -30_deg, 30_deg), 0.1, 1)[0];
  EXPECT_EQ(ahead.range, 3.0);  // sonar 0
  EXPECT_NEAR(ahead.angle, 0.0, 1e-12);
  // A span across the back, given counter-clockwise from 135 to 225 deg, holds sonar 8.
  EXPECT_EQ(sample(nearestEcho(r, 135_deg, 225_deg), 0.1, 1)[0].range, 0.1);
  EXPECT_EQ(toString(left), "0.800 m at 67.5 deg");
}

TEST(Sensing, NearestEchoTiesGoToTheSonarNearestTheSpansStart) {
  Robot r = ringWith([](int) { return 2.0; });
  EXPECT_NEAR(sample(nearestEcho(r, 45_deg, 135_deg), 0.1, 1)[0].angle, 45_deg, 1e-12);
  EXPECT_NEAR(sample(nearestEcho(r, -90_deg, 90_deg), 0.1, 1)[0].angle, -90_deg, 1e-12);
}

TEST(Sensing, NearestEchoRefusesASpanWithoutSonars) {
  Robot r = ringWith([](int) { return 2.0; });
  EXPECT_THROW((void)nearestEcho(r, 1_deg, 2_deg), UsageError);  // between sonars 0 and 1
  EXPECT_THROW((void)nearestEcho(r, 1.0, 0.5), UsageError);      // backwards
}

TEST(Sensing, AtPlaceOccursWhenTheRobotComesWithinReach) {
  Robot r(nomadSpec(), ScriptedSensors{.odometry = [](double t) { return Pose2{Point2{t, 0}, 0}; }});
  EXPECT_NEAR(*firstOccurrence(atPlace(r, Point2{2.02, 0}), 0.1, 100), 1.8, 1e-9);  // 30 cm by default
  EXPECT_NEAR(*firstOccurrence(atPlace(r, Point2{2.02, 0}, 5_cm), 0.1, 100), 2.0, 1e-9);
}

}  // namespace
}  // namespace frob
