// Determinism: the golden-hash test per reference world (as Box2D's test_determinism.c): fixed dt,
// step count and scripted commands, hash of every pose; and runs repeated, threaded and reseeded.
// When a change is meant to change trajectories, see README, "Contributing", for updating the hashes.
#include "frob/worlds/fnv.hpp"
#include "frob/worlds/recorder.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <string>

namespace frob::worlds {
namespace {

// A fixed scripted command for robot `i` at step `k`: alternating turns, and a speed that follows
// the front sonar (so noise reaches the trajectory), backing off when it reads close.
Wheels script(std::int64_t k, std::size_t i, const SensorFrame& f) {
  const int phase = static_cast<int>((k / 150 + static_cast<std::int64_t>(i)) % 4);
  const double front = f.sonar.empty() ? 6.5 : f.sonar[0];
  if (front < 0.5) return {.forward = -0.1, .turn = 0.8};
  return {.forward = std::min(0.5, 0.3 * front), .turn = phase == 1 ? 0.6 : phase == 3 ? -0.4 : 0.0};
}

// Runs `name` for `steps` steps under the script and returns the hash of every true pose.
std::uint64_t trajectoryHash(const WorldDef& world, int steps, int threads = 1) {
  Simulation sim(world, {.threads = threads});
  Recorder rec({.keepSteps = false});
  std::vector<Wheels> wheels(sim.robotCount());
  for (int k = 0; k < steps; ++k) {
    sim.sense();
    for (std::size_t i = 0; i < sim.robotCount(); ++i) wheels[i] = script(k, i, sim.frame(i));
    rec.record(sim, wheels);
    sim.step(wheels);
  }
  return rec.trajectoryHash();
}

// Golden hashes for 1000 steps at 100 Hz. They hold for Debian 12 x86_64, g++ 12, Box2D 2.4.1,
// -O2 -ffp-contract=off (RelWithDebInfo). Another compiler, flags or libm may change them; then
// check the trajectories by eye (frob render) before updating the constants.
TEST(Determinism, GoldenTrajectoryHashPerReferenceWorld) {
  const std::map<std::string, std::uint64_t> golden = {
      {"empty", 0xbd6db8a53f67dd38ULL},     {"corridor", 0xacf2cceb79de432aULL}, {"maze", 0x9cd1be32baddffd9ULL},  {"office", 0xb0a8d7614e324ae4ULL},
      {"obstacles", 0xe93408c3a153628fULL}, {"mesh", 0xc168a649a4448584ULL},     {"arena", 0x087a4b24ee4f5d6cULL},
  };
  for (const WorldEntry& e : referenceWorlds()) {
    const std::uint64_t h = trajectoryHash(*loadReferenceWorld(e.name), 1000);
    auto expected = golden.find(std::string(e.name));
    ASSERT_NE(expected, golden.end()) << "no golden hash for " << e.name;
    EXPECT_EQ(h, expected->second) << e.name << ": actual hash 0x" << std::hex << h;
    if (h != expected->second) std::printf("      {\"%s\", 0x%016" PRIx64 "ULL},\n", e.name.data(), h);
  }
}

// The fingerprint that keys results cached from runs (the fair hidden worlds) is a golden hash too:
// when the simulation changes, it changes, and so do the caches' keys.
TEST(Determinism, TheSimulationFingerprintIsPinned) {
  const std::uint64_t h = simulationFingerprint();
  EXPECT_EQ(h, 0x15e17255428197bbULL) << "actual fingerprint 0x" << std::hex << h;
  EXPECT_EQ(simulationFingerprint(), h);
}

TEST(Determinism, HundredRepeatedRunsAreBitIdentical) {
  const WorldDef maze = *loadReferenceWorld("maze");
  const WorldDef arena = *loadReferenceWorld("arena");
  const std::uint64_t first = trajectoryHash(maze, 300), arenaFirst = trajectoryHash(arena, 300);
  for (int run = 1; run < 100; ++run) {
    ASSERT_EQ(trajectoryHash(maze, 300), first) << "run " << run;
    ASSERT_EQ(trajectoryHash(arena, 300, 1 + run % 3), arenaFirst) << "run " << run;
  }
}

TEST(Determinism, AnotherSeedGivesAnotherRunWhereNoiseMatters) {
  WorldDef maze = *loadReferenceWorld("maze");  // its robot has noisy odometry and sonar
  const std::uint64_t a = trajectoryHash(maze, 600);
  maze.seed += 1;
  EXPECT_NE(trajectoryHash(maze, 600), a);  // the script reacts to (noisy) sonar
}

// 100 robots in the maze, placed as in the benchmark (tests/bench/worlds_bench.cpp), each with 16
// sonars of 5 rays: a golden hash of every sonar reading and pose, so that changes to the ray
// caster's data layout or traversal (robots seeing robots, pillars, walls) stay bit-identical.
// Same platform note as above; also holds for clang-16.
TEST(Determinism, GoldenSonarHashInACrowdedMaze) {
  WorldDef w = *loadReferenceWorld("maze");
  const RobotDef proto = w.robots.at(0);
  w.robots.clear();
  for (int k = 0; k < 100; ++k) {
    const int cell = (k * 37) % 256;
    RobotDef r = proto;
    r.start = {.position = Point2((cell % 16 + 0.5) * 1.25, (cell / 16 + 0.5) * 1.25), .heading = 0.7 * k};
    r.sonar.count = 16;
    r.sonar.rays = 5;
    w.robots.push_back(r);
  }
  auto run = [&](int threads) {
    Simulation sim(w, {.threads = threads});
    std::vector<Wheels> wheels(sim.robotCount());
    Fnv1a h;  // over the bits of every reading and pose
    auto mix = [&](double v) { h.add(v); };
    for (int k = 0; k < 200; ++k) {
      sim.sense();
      for (std::size_t i = 0; i < sim.robotCount(); ++i) {
        for (double s : sim.frame(i).sonar) mix(s);
        const Pose2 p = sim.truePose(i);
        mix(p.position.x()), mix(p.position.y()), mix(p.heading);
        wheels[i] = script(k, i, sim.frame(i));
      }
      sim.step(wheels);
    }
    return h.value();
  };
  const std::uint64_t golden = 0x377d5a4f4a1a6d27ULL;
  const std::uint64_t h = run(1);
  EXPECT_EQ(h, golden) << "actual hash 0x" << std::hex << h;
  EXPECT_EQ(run(2), h);
}

}  // namespace
}  // namespace frob::worlds
