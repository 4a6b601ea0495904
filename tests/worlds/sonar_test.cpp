// Sonar geometry (simulation.cpp and ray_caster.cpp): distances, specular loss, nearest echo,
// other robots, and noise that follows the seed.
#include "frob/worlds/simulation.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace frob::worlds {
namespace {

using namespace frob::literals;
using testing::ideal;

// A robot of radius 0.2 at (1, 2) facing +x, one sonar on its axis, and a wall at x = 3.
std::string facingWall(double noise, double headingDeg = 0) {
  return R"(
    size = [10, 4]
    enclosed = false
    seed = 11
    [[wall]]
    from = [3, 0]
    to = [3, 4]
    [[robot]]
    start = [1, 2]
    radius = 0.2
    heading_deg = )" +
         std::to_string(headingDeg) + R"(
    sonar = { angles_deg = [0], noise = )" +
         std::to_string(noise) + " }\n";
}

TEST(Sonar, ReadsAWallAheadAtItsDistance) {
  // The sensor sits on the rim (x = 1.2): the wall is 1.8 m away. The central ray of the cone is
  // perpendicular to the wall, so without noise the reading is exact up to Box2D's float positions.
  Simulation sim(ideal(facingWall(0.0)));
  sim.sense();
  EXPECT_NEAR(sim.frame(0).sonar[0], 1.8, 1e-6);
}

TEST(Sonar, NoisyReadingsStayWithinFourSigma) {
  // Noise is Gaussian with standard deviation 1% of the range (0.018 m here). Over 200 readings,
  // every one lies within 4 sigma (a miss has probability 6e-5 each) and the mean within 4 sigma/sqrt(200).
  Simulation sim(ideal(facingWall(0.01)));
  double sum = 0;
  for (int k = 0; k < 200; ++k) {
    sim.sense();
    EXPECT_NEAR(sim.frame(0).sonar[0], 1.8, 4 * 0.018);
    sum += sim.frame(0).sonar[0];
    sim.step(std::vector<Wheels>(1));
  }
  EXPECT_NEAR(sum / 200, 1.8, 4 * 0.018 / std::sqrt(200.0));
}

TEST(Sonar, AGrazingWallBeyondTheCutoffReadsMaxRange) {
  // Facing 60 degrees away from the wall's normal: every ray of the 25 degree cone meets the wall
  // at 47.5 to 72.5 degrees, beyond the 22.5 degree cutoff, and is reflected away.
  Simulation sim(ideal(facingWall(0.0, 60)));
  sim.sense();
  EXPECT_EQ(sim.frame(0).sonar[0], 6.5);
  // At 20 degrees the central ray still echoes.
  Simulation near(ideal(facingWall(0.0, 20)));
  near.sense();
  EXPECT_LT(near.frame(0).sonar[0], 6.5);
}

TEST(Sonar, NothingInRangeReadsMaxRange) {
  Simulation sim(ideal(R"(
    size = [20, 20]
    enclosed = false
    [[wall]]
    from = [15, 0]
    to = [15, 20]
    [[robot]]
    start = [2, 10]
    sonar = { angles_deg = [0] }
  )"));
  sim.sense();
  EXPECT_EQ(sim.frame(0).sonar[0], 6.5);
}

TEST(Sonar, InACornerTheNearerWallWins) {
  // A step-shaped corner: the upper half of the cone meets a near wall at x = 2, the lower half a
  // far wall at x = 4. The wall joining them runs along the rays and is never heard. The reading is
  // the nearest echoing ray: the one at +6.25 degrees reaching x = 2.
  Simulation sim(ideal(R"(
    size = [6, 4]
    enclosed = false
    [[wall]]
    polyline = [[2, 3.9], [2, 2.05], [4, 2.05], [4, 0.1]]
    [[robot]]
    start = [1, 2]
    radius = 0.2
    sonar = { angles_deg = [0], rays = 5, cone_deg = 25, noise = 0 }
  )"));
  sim.sense();
  EXPECT_NEAR(sim.frame(0).sonar[0], 0.8 / std::cos(6.25_deg), 1e-5);
}

TEST(Sonar, ReadingsAreClampedToTheMinimumRange) {
  Simulation sim(ideal(R"(
    size = [6, 4]
    enclosed = false
    [[wall]]
    from = [1.3, 0]
    to = [1.3, 4]
    [[robot]]
    start = [1, 2]
    radius = 0.2
    sonar = { angles_deg = [0], noise = 0 }
  )"));
  sim.sense();
  EXPECT_EQ(sim.frame(0).sonar[0], 0.15);  // the wall is 0.1 m from the sensor
}

TEST(Sonar, RobotsSeeEachOtherAndPillars) {
  Simulation sim(ideal(R"(
    size = [10, 4]
    enclosed = false
    [[wall]]
    circle = [1, 3.2]
    radius = 0.5
    [[robot]]
    start = [1, 1]
    radius = 0.2
    sonar = { angles_deg = [0, 90], noise = 0 }
    [[robot]]
    start = [4, 1]
    radius = 0.3
    sonar = { count = 0 }
  )"));
  sim.sense();
  EXPECT_NEAR(sim.frame(0).sonar[0], (4 - 0.3) - 1.2, 1e-5);    // the other robot's near side
  EXPECT_NEAR(sim.frame(0).sonar[1], (3.2 - 0.5) - 1.2, 1e-5);  // the pillar's near side
}

// Robots alike share one set of ray directions; robots unlike must each keep their own.
TEST(Sonar, RobotsWithDifferentSonarsEachReadWithTheirOwn) {
  const std::string a = R"(
    [[robot]]
    start = [2, 2]
    heading_deg = 10
    sonar = { count = 16, rays = 5, noise = 0 }
  )";
  const std::string b = R"(
    [[robot]]
    start = [8, 8]
    heading_deg = 10
    sonar = { count = 6, rays = 3, cone_deg = 60, noise = 0 }
  )";
  const std::string room = "size = [10, 10]\n";  // the robots 8.5 m apart: out of each other's range
  auto readings = [](const std::string& world, std::size_t robot) {
    Simulation sim(ideal(world));
    sim.sense();
    return sim.frame(robot).sonar;
  };
  const std::vector<double> together0 = readings(room + a + b, 0), together1 = readings(room + a + b, 1);
  ASSERT_EQ(together0.size(), 16u);
  ASSERT_EQ(together1.size(), 6u);
  EXPECT_EQ(together0, readings(room + a, 0));
  EXPECT_EQ(together1, readings(room + b, 0));
  std::string narrow = b;  // the same sonars with the default 25 degree cones read otherwise, so a mix-up shows
  narrow.replace(narrow.find(", cone_deg = 60"), 15, "");
  EXPECT_NE(together1, readings(room + narrow, 0));
}

TEST(Sonar, TheSameSeedGivesTheSameNoiseAndAnotherSeedOther) {
  auto readings = [](std::uint64_t seed) {
    Simulation sim(ideal(facingWall(0.05)), {.seed = seed});
    std::vector<double> r;
    for (int k = 0; k < 50; ++k) {
      sim.sense();
      r.push_back(sim.frame(0).sonar[0]);
      sim.step(std::vector<Wheels>(1));
    }
    return r;
  };
  EXPECT_EQ(readings(1), readings(1));
  EXPECT_NE(readings(1), readings(2));
}

TEST(Sonar, ARingOfSixteenSeesARoomAllAround) {
  // In the middle of a 4 x 4 room every sonar hears a wall within 2 * sqrt(2) m, except the four
  // that point into corners: every ray of theirs meets a wall 32.5 to 57.5 degrees from its normal.
  Simulation sim(ideal("size = [4, 4]\n[[robot]]\nstart = [2, 2]\nsonar = { noise = 0 }\n"));
  sim.sense();
  ASSERT_EQ(sim.frame(0).sonar.size(), 16u);
  EXPECT_NEAR(sim.frame(0).sonar[0], 2 - 0.23, 1e-5);
  EXPECT_NEAR(sim.frame(0).sonar[4], 2 - 0.23, 1e-5);
  for (int j = 0; j < 16; ++j) {
    if (j % 4 == 2)
      EXPECT_EQ(sim.frame(0).sonar[j], 6.5) << j;
    else
      EXPECT_LT(sim.frame(0).sonar[j], 2.0 * std::sqrt(2.0)) << j;
  }
}

// What frob/README.md, robot.hpp and lesson 1 tell students, with the Nomad's defaults: a wall
// alongside, 0.5 m to the left, echoes in sonar 4 (at 0.5 - 0.23 m from the rim) and in sonars 3
// and 5 (22.5 degrees off, within the cone and cutoff); the 45-degree sonars 2 and 6 hear nothing.
TEST(Sonar, TheDiagonalSonarsNeverHearAWallAlongside) {
  Simulation sim(ideal(R"(
    size = [10, 4]
    enclosed = false
    [[wall]]
    from = [0, 2.5]
    to = [10, 2.5]
    [[robot]]
    start = [5, 2]
    sonar = { noise = 0 }
  )"));
  sim.sense();
  const std::vector<double>& s = sim.frame(0).sonar;
  ASSERT_EQ(s.size(), 16u);
  EXPECT_NEAR(s[4], 0.5 - 0.23, 1e-6);  // Box2D keeps positions in floats
  EXPECT_LT(s[3], 6.5);
  EXPECT_LT(s[5], 6.5);
  EXPECT_EQ(s[2], 6.5);
  EXPECT_EQ(s[6], 6.5);
}

// A robot that has not moved reads again what its cones met before, without casting them (while
// no robot moves): a robot that turns on the spot, or one that others come near, must not.

// Turning on the spot keeps the centre to the bit and changes what the cones meet. Beside a robot
// driving far away (every cone cast anew each step), readings are those beside one standing still.
TEST(Sonar, ARobotTurningOnTheSpotHearsAsIfEveryConeWereCastAnew) {
  const auto readings = [](double farSpeed) {
    Simulation sim(ideal(R"(
      size = [30, 6]
      seed = 3
      [[wall]]
      from = [0.5, 0]
      to = [4, 6]
      [[robot]]
      start = [2, 2]
      sonar = { noise = 0 }
      [[robot]]
      start = [25, 3]
      sonar = { noise = 0 }
    )"));
    std::vector<std::vector<double>> out;
    for (const double turn : {0.0, 0.8, 0.0, -0.5, 0.0}) {
      for (int k = 0; k < 60; ++k) {
        sim.sense();
        out.push_back(sim.frame(0).sonar);
        sim.step(std::vector<Wheels>{{0.0, turn}, {farSpeed, 0.0}});
      }
    }
    EXPECT_EQ(sim.truePose(0).position, Point2(2.0f, 2.0f)) << "the robot left its spot: the test no longer turns on the spot";
    return out;
  };
  const std::vector<std::vector<double>> still = readings(0.0), cast = readings(0.3);
  ASSERT_EQ(still.size(), cast.size());
  for (std::size_t k = 0; k < still.size(); ++k) {
    ASSERT_EQ(still[k], cast[k]) << "step " << k;
  }
  EXPECT_NE(still.front(), still.back()) << "the turns changed nothing the sonars hear: the test proves nothing";
}

// Another robot driving up to one that stands still is heard coming.
TEST(Sonar, AStillRobotHearsAnotherComeNear) {
  Simulation sim(ideal(R"(
    size = [12, 4]
    enclosed = false
    [[robot]]
    start = [1, 2]
    radius = 0.2
    sonar = { angles_deg = [0], noise = 0 }
    [[robot]]
    start = [9, 2]
    heading_deg = 180
    radius = 0.3
    sonar = { count = 0 }
  )"));
  for (int k = 0; k < 3000 && sim.truePose(1).position.x() > 3.0; ++k) {
    sim.sense();
    sim.step(std::vector<Wheels>{{}, {0.5, 0.0}});
  }
  sim.step(std::vector<Wheels>{{}, {}});  // one more step, so that no robot is where it was sensed last
  sim.sense();
  EXPECT_LT(sim.truePose(1).position.x(), 3.0);
  EXPECT_NEAR(sim.frame(0).sonar[0], (sim.truePose(1).position.x() - 0.3) - 1.2, 1e-5);  // its near side
}

}  // namespace
}  // namespace frob::worlds
