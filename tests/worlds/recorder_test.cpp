// The recorder: what it keeps per step and the trajectory hash.
#include "frob/worlds/recorder.hpp"

#include "scene.hpp"

#include <gtest/gtest.h>

#include <string_view>

namespace frob::worlds {
namespace {

TEST(Recorder, KeepsEveryRobotAtEveryStep) {
  Simulation sim(testing::ideal("size = [4, 4]\n[[robot]]\nstart = [1, 1]\n[[robot]]\nstart = [3, 3]\n"));
  Recorder rec;
  const std::vector<Wheels> wheels = {{.forward = 0.2}, {.turn = 0.5}};
  const std::vector<Picture> pictures = {circle(1.0), {}};
  for (int k = 0; k < 10; ++k) {
    sim.sense();
    rec.record(sim, wheels, pictures);
    sim.step(wheels);
  }
  ASSERT_EQ(rec.steps().size(), 10u);
  EXPECT_EQ(rec.count(), 10);
  const StepRecord& s = rec.steps()[4];
  EXPECT_EQ(s.step, 4);
  EXPECT_DOUBLE_EQ(s.time, 0.04);
  ASSERT_EQ(s.robots.size(), 2u);
  EXPECT_EQ(s.robots[0].wheels, wheels[0]);
  EXPECT_EQ(s.robots[0].picture, circle(1.0));
  EXPECT_TRUE(s.robots[1].picture.empty());
  EXPECT_EQ(s.robots[1].sonar.size(), 16u);
  EXPECT_EQ(s.robots[0].odometry, s.robots[0].truePose);
  rec.last().robots[1].picture = disc(0.5);  // the run loop may attach pictures afterwards
  EXPECT_EQ(rec.steps().back().robots[1].picture, disc(0.5));
}

// A window keeps only the newest steps, the same as a full recording's, and the same hash.
TEST(Recorder, AWindowKeepsTheNewestStepsOnly) {
  const char* world = "size = [4, 4]\n[[robot]]\nstart = [1, 1]\n";
  Simulation a(testing::scene(world)), b(testing::scene(world));
  Recorder all, newest({.window = 3});
  const std::vector<Wheels> wheels = {{.forward = 0.2, .turn = 0.3}};
  for (int k = 0; k < 50; ++k) {
    for (auto [sim, rec] : {std::pair{&a, &all}, std::pair{&b, &newest}}) {
      sim->sense();
      rec->record(*sim, wheels);
      sim->step(wheels);
    }
  }
  ASSERT_EQ(newest.steps().size(), 3u);
  EXPECT_EQ(newest.count(), 50);
  EXPECT_EQ(newest.steps().front().step, 47);
  EXPECT_EQ(newest.steps().back().robots[0].truePose, all.steps().back().robots[0].truePose);
  EXPECT_EQ(newest.trajectoryHash(), all.trajectoryHash());
}

TEST(Recorder, HashIsFnv1aOverThePoseBytesAndKeepsOnlyTheHashWhenAsked) {
  // Expected values from outside this code: FNV-1a's published test vectors ("a", "foobar"), and
  // the hash of the 24 little-endian bytes of (1.5, -2.25, 0.5) as three doubles, computed in Python:
  //   h = 0xcbf29ce484222325; for c in struct.pack('<ddd', 1.5, -2.25, 0.5): h = ((h ^ c) * 0x100000001b3) % 2**64
  EXPECT_EQ(Fnv1a().add(std::string_view("a")).value(), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(Fnv1a().add(std::string_view("foobar")).value(), 0x85944171f73967e8ULL);
  const Pose2 pose{Point2(1.5, -2.25), 0.5};
  EXPECT_EQ(hashPose(0xcbf29ce484222325ULL, pose), 0x3b66d60d1679445bULL);
  EXPECT_EQ(hashPose(hashPose(0xcbf29ce484222325ULL, pose), Pose2{}), 0x4c04a4ad94c1147bULL);  // then 24 zero bytes

  Simulation sim(testing::scene("size = [4, 4]\n[[robot]]\nstart = [1, 1]\n"));
  Recorder full, hashOnly({.keepSteps = false});
  for (int k = 0; k < 5; ++k) {
    sim.sense();
    full.record(sim, std::vector<Wheels>(1, {.forward = 0.3}));
    hashOnly.record(sim, std::vector<Wheels>(1, {.forward = 0.3}));
    sim.step(std::vector<Wheels>(1, {.forward = 0.3}));
  }
  EXPECT_TRUE(hashOnly.steps().empty());
  EXPECT_EQ(hashOnly.trajectoryHash(), full.trajectoryHash());
  std::uint64_t h = kFnvOffset;
  for (const StepRecord& s : full.steps()) h = hashPose(h, s.robots[0].truePose);
  EXPECT_EQ(full.trajectoryHash(), h);
}

}  // namespace
}  // namespace frob::worlds
