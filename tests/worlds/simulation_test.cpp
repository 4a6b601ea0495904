// The simulation: driving, walls that stop robots, bumpers, odometry, keys, several robots, threads.
#include "frob/worlds/simulation.hpp"

#include "frob/errors.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

namespace frob::worlds {
namespace {

using namespace frob::literals;
using testing::drive;
using testing::ideal;
using testing::scene;

TEST(Simulation, TimeIsStepsTimesDt) {
  Simulation sim(ideal("size = [4, 4]\n[[robot]]\nstart = [2, 2]\n"), {.dt = 0.02});
  drive(sim, 50, {});
  EXPECT_EQ(sim.stepCount(), 50);
  EXPECT_DOUBLE_EQ(sim.time(), 50 * 0.02);
}

// A programmer's mistakes are caught in every build, release too (FROB_ASSERT, not assert).
TEST(Simulation, ANonPositiveStepOrAWheelCountOtherThanTheRobotsIsAUsageError) {
  const WorldDef world = ideal("size = [4, 4]\n[[robot]]\nstart = [2, 2]\n");
  EXPECT_THROW(Simulation(world, {.dt = 0.0}), UsageError);
  Simulation sim(world);
  const std::vector<Wheels> two(2);
  EXPECT_THROW(sim.step(two), UsageError);
}

TEST(Simulation, RobotNamesTellRobotsApart) {
  Simulation sim(
      ideal("size = [8, 2]\n[[robot]]\nname = \"a\"\nstart = [1, 1]\n[[robot]]\nstart = [3, 1]\n"
            "[[robot]]\nname = \"b\"\nstart = [5, 1]\n[[robot]]\nname = \"b\"\nstart = [7, 1]\n"));
  EXPECT_EQ(sim.robotName(0), "a");
  EXPECT_EQ(sim.robotName(1), "robot1");
  EXPECT_EQ(sim.robotName(2), "b#2");
  EXPECT_EQ(sim.robotName(3), "b#3");
}

TEST(Simulation, DrivesForwardAndTurnsWithinItsLimits) {
  Simulation sim(ideal(R"(
    size = [20, 20]
    [[robot]]
    start = [2, 10]
    drive = { max_speed = 0.5, acceleration = 1.0, max_turn_rate = 1.0, turn_acceleration = 2.0 }
  )"));
  drive(sim, 100, {.forward = 2.0});  // asks for more than the limit
  // Accelerates at 1 m/s^2 to 0.5 m/s over 0.5 s (0.125 m), then cruises 0.5 s: 0.375 m in all.
  EXPECT_NEAR(sim.truePose(0).position.x(), 2.375, 0.01);
  sim.sense();
  EXPECT_NEAR(sim.frame(0).velocity, 0.5, 1e-5);
  drive(sim, 100, {.turn = 1.0});
  sim.sense();
  EXPECT_NEAR(sim.frame(0).turnRate, 1.0, 1e-5);
}

// A late start: the wheels do not answer for start_delay seconds, then drive as usual (0.5 s to
// reach 0.5 m/s, as above: 0.375 m in the second after the delay).
TEST(Simulation, AStartDelayHoldsTheWheelsUntilIt) {
  Simulation sim(ideal(R"(
    size = [20, 20]
    [[robot]]
    start = [2, 10]
    drive = { max_speed = 0.5, acceleration = 1.0, start_delay = 1.5 }
  )"));
  drive(sim, 150, {.forward = 2.0});
  EXPECT_EQ(sim.truePose(0).position.x(), 2.0);
  drive(sim, 100, {.forward = 2.0});
  EXPECT_NEAR(sim.truePose(0).position.x(), 2.375, 0.01);
}

TEST(Simulation, AWallStopsARobotAndItsBumperFiresOnce) {
  // A robot 2 m from a wall drives straight at it for 10 s: it must stop at the wall, not pass it.
  Simulation sim(ideal(R"(
    size = [6, 4]
    enclosed = false
    [[wall]]
    from = [4, 0]
    to = [4, 4]
    [[robot]]
    start = [2, 2]
    bumpers = 8
  )"));
  std::vector<BumperHit> hits;
  for (int k = 0; k < 1000; ++k) {
    sim.sense();
    hits.insert(hits.end(), sim.frame(0).bumps.begin(), sim.frame(0).bumps.end());
    sim.step(std::vector<Wheels>{{.forward = 0.6}});
    ASSERT_LT(sim.truePose(0).position.x(), 4.0 - 0.23) << "at step " << k;
  }
  // Box2D keeps a skin of about 1 cm between shapes (b2_polygonRadius) minus its slop.
  EXPECT_GT(sim.truePose(0).position.x(), 4.0 - 0.23 - 0.03);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].bumper, 0);
  EXPECT_NEAR(hits[0].angle, 0.0, 1_deg);
}

TEST(Simulation, BackingOffAndHittingAgainIsASecondContact) {
  Simulation sim(ideal(R"(
    size = [6, 4]
    [[robot]]
    start = [5, 2]
  )"));
  int hits = 0;
  for (int k = 0; k < 900; ++k) {
    sim.sense();
    hits += static_cast<int>(sim.frame(0).bumps.size());
    const double forward = k < 300 ? 0.5 : k < 500 ? -0.3 : 0.5;  // in, out, in again
    sim.step(std::vector<Wheels>{{.forward = forward}});
  }
  EXPECT_EQ(hits, 2);
}

TEST(Simulation, AFastRobotNeverTunnelsThroughAThinWall) {
  Simulation sim(ideal(R"(
    size = [6, 4]
    enclosed = false
    [[wall]]
    from = [3, 0]
    to = [3, 4]
    [[robot]]
    start = [1, 2]
    radius = 0.05
    drive = { max_speed = 20, acceleration = 1000 }
  )"));
  drive(sim, 200, {.forward = 20});  // 20 cm per step, four times the robot's radius
  EXPECT_LT(sim.truePose(0).position.x(), 3.0 - 0.05);
}

TEST(Simulation, BumperReportsTheContactAngleRelativeToTheHeading) {
  // Heading 45 degrees into a wall on the east: the contact is 45 degrees to the right.
  Simulation sim(ideal(R"(
    size = [6, 6]
    enclosed = false
    [[wall]]
    from = [4, 0]
    to = [4, 6]
    [[robot]]
    start = [3, 1]
    heading_deg = 45
    bumpers = 8
  )"));
  std::vector<BumperHit> hits;
  for (int k = 0; k < 600; ++k) {
    sim.sense();
    hits.insert(hits.end(), sim.frame(0).bumps.begin(), sim.frame(0).bumps.end());
    sim.step(std::vector<Wheels>{{.forward = 0.5}});
  }
  ASSERT_EQ(hits.size(), 1u);  // sliding along the wall keeps the same bumper pressed
  EXPECT_NEAR(hits[0].angle, -45_deg, 1_deg);
  EXPECT_EQ(hits[0].bumper, 7);                        // sectors of 45 degrees counter-clockwise from the front
  EXPECT_NEAR(sim.truePose(0).heading, 45_deg, 1e-6);  // walls do not turn a synchro-drive robot
}

TEST(Simulation, OdometryWithoutNoiseIsTheTruePose) {
  Simulation sim(ideal("size = [10, 10]\n[[robot]]\nstart = [5, 5]\nheading_deg = 30\n"));
  for (int k = 0; k < 500; ++k) {
    sim.sense();
    EXPECT_EQ(sim.frame(0).odometry, sim.truePose(0));
    sim.step(std::vector<Wheels>{{.forward = 0.3, .turn = k < 250 ? 0.8 : -0.5}});
  }
}

// Statistics over many robots driving in parallel lanes, each with its own noise stream.
struct Drift {
  double alongVariance = 0, headingVariance = 0, distance = 0;
};

Drift measureDrift(double translation, double heading, int robots) {
  WorldDef w{.size = {40.0, 2.0 * robots + 2.0}};
  for (int i = 0; i < robots; ++i)
    w.robots.push_back(
        {.start = {.position = Point2(1.0, 2.0 + 2.0 * i)}, .sonar = {.count = 0}, .odometry = {.translation = translation, .heading = heading}});
  Simulation sim(w);
  drive(sim, 2000, {.forward = 0.6});  // about 11.7 m each
  Drift d;
  for (int i = 0; i < robots; ++i) {
    const Pose2 t = sim.truePose(i), o = sim.odometry(i);
    d.distance += (t.position.x() - 1.0) / robots;
    d.alongVariance += std::pow(o.position.x() - t.position.x(), 2) / robots;  // mean is 0: no bias
    d.headingVariance += std::pow(angleDiff(t.heading, o.heading), 2) / robots;
  }
  return d;
}

TEST(Simulation, OdometryDriftsAtTheConfiguredRate) {
  // Along-track error is a random walk: variance translation^2 * distance. With 200 robots the
  // sample variance has a relative standard error of sqrt(2/200) = 10%; we allow 35% (3.5 sigma).
  const Drift along = measureDrift(0.05, 0.0, 200);
  EXPECT_NEAR(along.alongVariance / (0.05 * 0.05 * along.distance), 1.0, 0.35);
  const Drift turn = measureDrift(0.0, 0.02, 200);
  EXPECT_NEAR(turn.headingVariance / (0.02 * 0.02 * turn.distance), 1.0, 0.35);
  EXPECT_EQ(turn.alongVariance > 0, true);  // a heading error bends the believed path
}

// Each step's dead reckoning waits for the next sense() (or step(), or odometry()): the belief is
// the same bits whether the robots are sensed every step, now and then, or never.
TEST(Simulation, OdometryIsTheSameWhetherOrNotTheRobotsAreSensed) {
  WorldDef w = ideal("size = [10, 10]\nseed = 3\n");
  for (int i = 0; i < 3; ++i)
    w.robots.push_back({.start = {.position = Point2(2.0, 2.0 + 2.0 * i)}, .odometry = {.translation = 0.05, .heading = 0.05, .turn = 0.05}});
  auto beliefs = [&](int senseEvery, bool askEachStep) {
    Simulation sim(w, {.threads = 2});
    std::vector<double> all;
    for (int k = 0; k < 200; ++k) {
      if (senseEvery > 0 && k % senseEvery == 0) sim.sense();
      if (askEachStep || k == 199)
        for (std::size_t i = 0; i < sim.robotCount(); ++i) all.push_back(sim.odometry(i).position.x()), all.push_back(sim.odometry(i).heading);
      sim.step(std::vector<Wheels>(sim.robotCount(), {.forward = 0.4, .turn = k < 100 ? 0.5 : -0.3}));
    }
    for (std::size_t i = 0; i < sim.robotCount(); ++i) all.push_back(sim.odometry(i).position.x());
    return all;
  };
  const std::vector<double> sensed = beliefs(1, true);
  EXPECT_EQ(beliefs(1, false).back(), sensed.back());
  EXPECT_EQ(beliefs(0, true), sensed);
  EXPECT_EQ(beliefs(7, true), sensed);
  EXPECT_EQ(beliefs(0, false).back(), sensed.back());
  EXPECT_GT(sensed.back(), 2.5);  // the belief followed the robot, which drove on from x = 2
}

TEST(Simulation, ScriptedKeysArriveAtTheirStep) {
  WorldDef w = ideal(R"(
    size = [4, 4]
    [[robot]]
    start = [1, 1]
    [[robot]]
    start = [3, 3]
    [[key]]
    time = 0.05
    key = "a"
    [[key]]
    time = 0.05
    key = "b"
    robot = 1
  )");
  Simulation sim(w, {.keys = {{.time = 0.1, .key = 'z'}}});
  std::vector<std::vector<char>> seen(2);
  for (int k = 0; k < 20; ++k) {
    sim.sense();
    for (int i = 0; i < 2; ++i)
      for (char c : sim.frame(i).keys) {
        seen[i].push_back(c);
        EXPECT_TRUE(k == 5 || k == 10) << k;
      }
    sim.step(std::vector<Wheels>(2));
  }
  EXPECT_EQ(seen[0], (std::vector<char>{'a', 'z'}));
  EXPECT_EQ(seen[1], (std::vector<char>{'a', 'b', 'z'}));
}

TEST(Simulation, RobotsCollideWithEachOtherAndBothFeelIt) {
  Simulation sim(ideal(R"(
    size = [8, 4]
    [[robot]]
    start = [2, 2]
    [[robot]]
    start = [6, 2]
    heading_deg = 180
  )"));
  int hits[2] = {0, 0};
  for (int k = 0; k < 600; ++k) {
    sim.sense();
    for (int i = 0; i < 2; ++i) hits[i] += static_cast<int>(sim.frame(i).bumps.size());
    sim.step(std::vector<Wheels>(2, {.forward = 0.5}));
  }
  EXPECT_EQ(hits[0], 1);
  EXPECT_EQ(hits[1], 1);
  EXPECT_GE(sim.truePose(1).position.x() - sim.truePose(0).position.x(), 2 * 0.23 - 0.02);
}

TEST(Simulation, NonFiniteCommandsStopTheRobotAndAreCounted) {
  Simulation sim(ideal("size = [4, 4]\n[[robot]]\nstart = [2, 2]\n"));
  drive(sim, 10, {.forward = NAN, .turn = INFINITY});
  EXPECT_EQ(sim.invalidCommands(0), 10u);
  EXPECT_EQ(sim.truePose(0).position, Point2(2, 2));
}

// `count` robots in lanes 2 m apart, without sonars, with the given slip and start spread.
WorldDef lanes(int count, double slip, StartSpreadDef spread, std::uint64_t seed = 1) {
  WorldDef w{.size = {40.0, 2.0 * count + 2.0}, .seed = seed};
  for (int i = 0; i < count; ++i)
    w.robots.push_back({.start = {.position = Point2(2.0, 2.0 + 2.0 * i)}, .startSpread = spread, .sonar = {.count = 0}, .drive = {.slip = slip}});
  return w;
}

// The relative error of each robot's achieved speed (forward, else turn rate) over the next
// `steps` steps, commanded `wheels` (already reached).
std::vector<double> slipOver(Simulation& sim, int steps, Wheels wheels) {
  std::vector<Pose2> before;
  for (std::size_t i = 0; i < sim.robotCount(); ++i) before.push_back(sim.truePose(i));
  drive(sim, steps, wheels);
  std::vector<double> error;
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    const double done =
        wheels.forward != 0 ? (sim.truePose(i).position - before[i].position).norm() : angleDiff(before[i].heading, sim.truePose(i).heading);
    error.push_back(done / ((wheels.forward != 0 ? wheels.forward : wheels.turn) * steps * sim.dt()) - 1.0);
  }
  return error;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
double deviation(const std::vector<double>& v) {
  const double m = mean(v);
  return std::sqrt(std::accumulate(v.begin(), v.end(), 0.0, [m](double s, double x) { return s + (x - m) * (x - m); }) /
                   static_cast<double>(v.size() - 1));
}
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double ma = mean(a), mb = mean(b);
  double ab = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ab += (a[i] - ma) * (b[i] - mb);
  return ab / static_cast<double>(a.size() - 1) / (deviation(a) * deviation(b));
}

// The wheels slip: over 300 robots the achieved speed and turn rate differ from those commanded
// by a relative error of deviation 3% (the sample deviation's relative standard error is 4%: we
// allow 20%), with no bias (4 standard errors), that changes slowly: over 0.1 s its correlation
// time of 2 s keeps exp(-0.05) = 0.95 of it (we ask for 0.8), while another seed draws another.
TEST(Simulation, WheelsSlipByASlowlyVaryingFewPercent) {
  for (const Wheels wheels : {Wheels{.forward = 0.4}, Wheels{.turn = 0.5}}) {
    Simulation sim(lanes(300, 0.03, {0, 0}));
    drive(sim, 100, wheels);  // up to speed
    const std::vector<double> first = slipOver(sim, 10, wheels), next = slipOver(sim, 10, wheels);
    EXPECT_NEAR(deviation(first), 0.03, 0.006);
    EXPECT_NEAR(mean(first), 0.0, 4 * 0.03 / std::sqrt(300.0));
    EXPECT_GT(correlation(first, next), 0.8);
    Simulation other(lanes(300, 0.03, {0, 0}, 2));
    drive(other, 100, wheels);
    EXPECT_LT(std::abs(correlation(first, slipOver(other, 10, wheels))), 0.25);  // independent: |r| < 4 / sqrt(300)
    Simulation exact(lanes(3, 0.0, {0, 0}));
    drive(exact, 100, wheels);
    for (double e : slipOver(exact, 10, wheels)) EXPECT_NEAR(e, 0.0, 1e-4);  // float positions: 2.4e-7 m of 0.04 m moved, several steps
  }
}

// Every robot really starts within its start spread of its start, each somewhere else, and its
// odometry begins at the start: the robot does not know where it really is.
TEST(Simulation, RobotsStartWithinTheirSpreadAndBelieveTheirStart) {
  const StartSpreadDef spread{.position = 0.02, .heading = 0.5_deg};
  Simulation sim(lanes(200, 0.0, spread)), again(lanes(200, 0.0, spread)), other(lanes(200, 0.0, spread, 2));
  double farthest = 0, mostTurned = 0;
  int differ = 0;
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    const Pose2 truth = sim.truePose(i), start = sim.robot(i).start;
    const double off = (truth.position - start.position).norm(), turned = std::abs(angleDiff(start.heading, truth.heading));
    EXPECT_LE(off, 0.02 + 1e-6);  // float positions
    EXPECT_LE(turned, 0.5_deg + 1e-6);
    farthest = std::max(farthest, off), mostTurned = std::max(mostTurned, turned);
    EXPECT_EQ(sim.odometry(i), start);
    EXPECT_EQ(again.truePose(i), truth);
    differ += other.truePose(i).position != truth.position;
  }
  EXPECT_GT(farthest, 0.018);  // spread over the disc, not at its centre
  EXPECT_GT(mostTurned, 0.45_deg);
  EXPECT_EQ(differ, 200);
  // Driving on, odometry follows the true motion from the believed start: the offset stays.
  drive(sim, 200, {.forward = 0.5, .turn = 0.3});
  const Pose2 truth = sim.truePose(0), belief = sim.odometry(0);
  EXPECT_GT((truth.position - belief.position).norm(), 1e-4);
  EXPECT_LT((truth.position - belief.position).norm(), 0.02 + 0.01 + 0.05);  // offset, its turn over 1 m, drift
}

// A known spread draws the start the robot believes anew in each run, anywhere in its disc (so no
// world, handed out or generated, starts at a pose that gives it away), and the true start lies
// within the start spread of that.
TEST(Simulation, AKnownSpreadDrawsTheStartTheRobotBelievesInEachRun) {
  const StartSpreadDef spread{.position = 0.02, .heading = 0.5_deg, .knownPosition = 0.25, .knownHeading = 20.0_deg};
  Simulation sim(lanes(200, 0.0, spread)), again(lanes(200, 0.0, spread)), other(lanes(200, 0.0, spread, 2));
  double farthest = 0, mostTurned = 0;
  int differ = 0;
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    const Pose2 start = sim.robot(i).start, known = sim.odometry(i), truth = sim.truePose(i);
    const double off = (known.position - start.position).norm(), turned = std::abs(angleDiff(start.heading, known.heading));
    EXPECT_LE(off, 0.25);
    EXPECT_LE(turned, 20.0_deg);
    EXPECT_LE((truth.position - known.position).norm(), 0.02 + 1e-6);  // float positions
    EXPECT_LE(std::abs(angleDiff(known.heading, truth.heading)), 0.5_deg + 1e-6);
    farthest = std::max(farthest, off), mostTurned = std::max(mostTurned, turned);
    EXPECT_EQ(again.odometry(i), known);
    differ += other.odometry(i).position != known.position;
  }
  EXPECT_GT(farthest, 0.24);  // over the disc, not at its centre
  EXPECT_GT(mostTurned, 19.0_deg);
  EXPECT_EQ(differ, 200);
}

// The point of slip and start spread: the same commands, replayed with another seed, end up
// elsewhere (a 30 s drive of some 12 m ends on average tens of centimetres away; we ask for 10 cm
// over seven seeds), and with the same seed, exactly where they did. An ideal robot retraces them.
TEST(Simulation, ARecordedCommandSequenceDoesNotRetraceItsPath) {
  auto finalPose = [](const WorldDef& world, std::uint64_t seed) {
    Simulation sim(world, {.seed = seed});
    for (int k = 0; k < 3000; ++k) drive(sim, 1, {.forward = 0.4, .turn = (k / 500) % 2 == 0 ? 0.0 : 0.3});  // straight legs and arcs
    return sim.truePose(0);
  };
  const char* room = "size = [20, 20]\n[[robot]]\nstart = [4, 4]\n";
  const Pose2 recorded = finalPose(scene(room), 1);
  double apart = 0;
  for (std::uint64_t seed = 2; seed <= 8; ++seed) apart += (finalPose(scene(room), seed).position - recorded.position).norm() / 7;
  EXPECT_GT(apart, 0.1);
  EXPECT_EQ(finalPose(scene(room), 1), recorded);
  EXPECT_EQ(finalPose(ideal(room), 1), finalPose(ideal(room), 2));  // the old replay cheat's robot
}

TEST(Simulation, EnclosedWorldsHaveFourMoreWalls) {
  Simulation sim(ideal("size = [4, 4]\n[[wall]]\nfrom = [1, 1]\nto = [1, 2]\n"));
  EXPECT_EQ(sim.world().walls.size(), 1u);
  EXPECT_EQ(sim.walls().size(), 5u);
  EXPECT_EQ(sim.robotCount(), 0u);
  drive(sim, 3, {});  // a world without robots still steps
}

TEST(Simulation, SensingInParallelGivesBitIdenticalResults) {
  WorldDef w = ideal(R"(
    size = [12, 12]
    seed = 5
    [[wall]]
    circle = [6, 6]
    radius = 1
  )");
  for (int i = 0; i < 30; ++i)
    w.robots.push_back({.start = {.position = Point2(1.0 + (i % 6) * 2.0, 1.0 + (i / 6) * 2.0 + (i / 6 >= 2 ? 2.0 : 0.0)), .heading = 0.3 * i},
                        .sonar = {.noise = 0.05},
                        .odometry = {.translation = 0.05, .heading = 0.05, .turn = 0.05}});
  ASSERT_TRUE(checkWorld(w).ok()) << checkWorld(w).error();
  auto run = [&](int threads) {
    Simulation sim(w, {.threads = threads});
    std::vector<double> all;
    for (int k = 0; k < 300; ++k) {
      sim.sense();
      std::vector<Wheels> wheels;
      for (std::size_t i = 0; i < sim.robotCount(); ++i) {
        const SensorFrame& f = sim.frame(i);
        all.insert(all.end(), f.sonar.begin(), f.sonar.end());
        all.push_back(f.odometry.position.x());
        wheels.push_back({.forward = f.sonar[0] > 1.0 ? 0.5 : 0.0, .turn = f.sonar[0] > 1.0 ? 0.0 : 1.0});
      }
      sim.step(wheels);
    }
    return all;
  };
  const std::vector<double> one = run(1);
  EXPECT_EQ(run(2), one);
  EXPECT_EQ(run(3), one);
}

}  // namespace
}  // namespace frob::worlds
