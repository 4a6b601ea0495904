// The recorder: what it keeps per step and the trajectory hash.
#include "frob/worlds/recorder.hpp"

#include "scene.hpp"

#include <gtest/gtest.h>

namespace frob::worlds {
namespace {

TEST(Recorder, KeepsEveryRobotAtEveryStep) {
  Simulation sim(testing::scene("size = [4, 4]\n[[robot]]\nstart = [1, 1]\n[[robot]]\nstart = [3, 3]\n"));
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

TEST(Recorder, HashIsFnv1aOverThePoseBytesAndKeepsOnlyTheHashWhenAsked) {
  // FNV-1a of no bytes is the offset basis; one pose of zeros folds 24 zero bytes.
  std::uint64_t expected = kFnvOffset;
  for (int b = 0; b < 24; ++b) expected *= 0x100000001b3ULL;
  EXPECT_EQ(hashPose(kFnvOffset, Pose2{}), expected);
  EXPECT_NE(hashPose(kFnvOffset, Pose2{.heading = 1e-300}), expected);

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
