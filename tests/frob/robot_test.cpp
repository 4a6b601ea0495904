#include "frob/robot.hpp"

#include "../bench/wall_follower.hpp"
#include "frob/calculus.hpp"
#include "frob/errors.hpp"
#include "frob/sampling.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

using namespace literals;

Robot approachingWall() {
  // The front sonar sees a wall 1 m away closing at 0.5 m/s; every other sonar reads its own index.
  return Robot(nomadSpec(), ScriptedSensors{
                                .sonar = [](double t, int i) { return i == 0 ? 1.0 - 0.5 * t : 1.0 + i; },
                                .odometry =
                                    [](double t) {
                                      return Pose2{Point2{0.5 * t, 0.0}, 0.1};
                                    },
                                .velocity = [](double) { return 0.5; },
                                .bumps =
                                    [](double t) {
                                      return t > 1.95 && t < 2.05 ? std::vector<BumperHit>{{0, 0.0}} : std::vector<BumperHit>{};
                                    },
                            });
}

TEST(Robot, NamedSonarsPointWhereTheirNamesSay) {
  Robot r = approachingWall();
  EXPECT_EQ(r.sonarNearest(0.0), 0);
  EXPECT_EQ(r.sonarNearest(pi / 2), 4);
  EXPECT_EQ(r.sonarNearest(-pi / 2), 12);
  EXPECT_EQ(r.sonarNearest(pi), 8);
  EXPECT_EQ(sample(leftSonar(r), 0.1, 1)[0], 5.0);
  EXPECT_EQ(sample(rightSonar(r), 0.1, 1)[0], 13.0);
  EXPECT_EQ(sample(backSonar(r), 0.1, 1)[0], 9.0);
  EXPECT_EQ(sample(sonars(r), 0.1, 1)[0].size(), 16u);
}

// Issue 18: sonar 16 of a ring of 16 is a mistake, not sonar 0. The error is a UsageError (a
// programmer's mistake, like FROB_ASSERT's), thrown where the sonar is named, with the caller's line.
TEST(Robot, ASonarOutsideTheRingIsRefusedNamingTheIndexAndTheRingSize) {
  Robot r = approachingWall();
  for (int i : {16, -3}) {
    try {
      (void)sonar(r, i);
      FAIL() << "sonar " << i << " was accepted";
    } catch (const UsageError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find("sonar(r, " + std::to_string(i) + ") does not exist"), std::string::npos) << m;
      EXPECT_NE(m.find("the ring has 16 sonars, 0 (front) to 15"), std::string::npos) << m;
      EXPECT_NE(m.find("robot_test.cpp:"), std::string::npos) << m;  // where the student named it
    }
  }
  EXPECT_EQ(sample(sonar(r, 15), 0.1, 1)[0], 16.0);  // the last one is there
}

TEST(Robot, OdometryAndVelocityReadTheFrame) {
  Robot r = approachingWall();
  std::vector<Point2> p = sample(place(r), 0.5, 3);
  EXPECT_EQ(p[2], Point2(0.5, 0.0));
  EXPECT_EQ(sample(orientation(r), 0.5, 1)[0], 0.1);
  EXPECT_EQ(sample(velocity(r), 0.5, 1)[0], 0.5);
}

TEST(Robot, BumperOccursWhenTheFrameReportsAContact) {
  auto hits = occurrences(bumper(approachingWall()), 0.1, 30);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].first, 2.0, 1e-12);
  EXPECT_EQ(hits[0].second.bumper, 0);
}

TEST(Robot, ThePapersStopitEvent) {
  // stopit r = predicate (time > timeMax || frontSonar r < 20)
  Robot r = approachingWall();
  double timeMax = 5.0;
  Event<Unit> stopit = predicate(time() > timeMax || frontSonar(r) < 20_cm);
  std::optional<double> t = firstOccurrence(stopit, 0.01, 1000);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 1.6, 0.01);  // 1 - 0.5 t < 0.2 from t = 1.6, found within one step
}

TEST(Robot, SensorsAreReadOncePerInstantHoweverOftenUsed) {
  int reads = 0;
  Robot r(nomadSpec(8), ScriptedSensors{.sonar = [&reads](double, int i) {
            if (i == 0) ++reads;
            return 1.0;
          }});
  Behavior<double> f = frontSonar(r);
  (void)sample(f + f * sonar(r, 0) + leftSonar(r), 0.1, 10);
  EXPECT_EQ(reads, 10);
}

TEST(Robot, ReadsAFrameItsOwnerRefreshesInPlace) {
  auto frame = std::make_shared<SensorFrame>();
  Robot r(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<double> front = frontSonar(r);
  Behavior<double> heading = orientation(r);
  Event<BumperHit> bumps = bumper(r);
  Clock clock(0.1);
  for (int k = 0; k < 3; ++k) {
    const Instant& now = k == 0 ? clock.now() : clock.advance();
    frame->sonar.assign(16, 1.0 + k);
    frame->odometry = Pose2{Point2{0.0, 0.0}, 0.1 * k};
    frame->bumps = k == 2 ? std::vector<BumperHit>{{3, 0.5}} : std::vector<BumperHit>{};
    EXPECT_EQ(front.at(now), 1.0 + k);
    EXPECT_EQ(heading.at(now), 0.1 * k);
    EXPECT_EQ(bumps.at(now).has_value(), k == 2);
    EXPECT_EQ(sonars(r).at(now).size(), 16u);
  }
}

TEST(Robot, AFrameWithTooFewSonarsIsAnErrorNotAStrayRead) {
  auto frame = std::make_shared<SensorFrame>();
  frame->sonar.assign(4, 1.0);
  Robot r(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<double> left = leftSonar(r);  // sonar 4 of 16
  EXPECT_THROW((void)left.at(Clock(0.1).now()), std::out_of_range);
}

// The core benchmark compares the paper's wall follower in Frob with a hand-written twin; they
// must compute the same commands, bit for bit, or the comparison means nothing.
TEST(Robot, TheBenchmarksWallFollowerAgreesWithItsHandWrittenTwin) {
  auto frame = std::make_shared<SensorFrame>();
  Robot r(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<Wheels> frob = bench::wallFollower(r);
  bench::HandWritten hand;
  Clock clock(0.01);
  for (int k = 0; k < 2000; ++k) {
    const Instant& now = k == 0 ? clock.now() : clock.advance();
    bench::fillFrame(*frame, now.step);
    ASSERT_EQ(frob.at(now), hand.step(*frame, now.time)) << "at step " << k;
  }
}

TEST(Robot, WheelsPairsForwardAndTurn) {
  Behavior<Wheels> w = wheels(10_cm, time());
  std::vector<Wheels> s = sample(w, 0.5, 2);
  EXPECT_EQ(s[1], (Wheels{0.1, 0.5}));
}

}  // namespace
}  // namespace frob
