// Tests of the controller's tasks on scripted sensors: each sonar reading is a function of time.
#include "wander.hpp"

#include <gtest/gtest.h>

namespace {

using namespace frob;

// A robot whose sonars all read `range(t)` metres at time t.
Robot robotSeeing(std::function<double(double)> range) {
  return Robot(nomadSpec(), ScriptedSensors{.sonar = [range](double t, int) { return range(t); }});
}

TEST(GoAhead, DrivesForwardWhileTheWayIsClear) {
  const std::vector<Wheels> w = sample(runTask(robotSeeing([](double) { return 3.0; }), wander::goAhead()), 0.1, 5);
  for (const Wheels& s : w) {
    EXPECT_DOUBLE_EQ(s.forward, 0.3);
    EXPECT_DOUBLE_EQ(s.turn, 0.0);
  }
}

TEST(Wander, TurnsOnceAWallIsNear) {
  // A wall 2 m ahead for the first second, 40 cm ahead after it.
  const std::vector<Wheels> w = sample(runTask(robotSeeing([](double t) { return t < 1.0 ? 2.0 : 0.4; }), wander::wander()), 0.1, 20);
  EXPECT_GT(w.front().forward, 0.0);
  EXPECT_DOUBLE_EQ(w.back().forward, 0.0);
  EXPECT_GT(w.back().turn, 0.0);
}

}  // namespace
