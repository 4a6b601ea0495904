// The wall_follow assignment graded as CI grades it, hidden checks included (test secret): the
// reference solution gets full marks, the starter nothing, and each typical wrong submission of
// tests/assignments/wall_follow/ exactly the partial score it deserves, failing the checks it
// should with a reason a student can act on. Course example 2 (the paper's rerror), copied as it
// is, does not pass: it follows the LEFT wall, 50 cm away, and stops where that wall ends.
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "wall_follow";
const std::string kRound = "goes round with the wall on its right";
const std::string kKeeps = "keeps 40 cm from the wall as it goes";
const std::string kUnseenRound = "goes round unseen rooms with the wall on its right";
const std::string kUnseenKeeps = "keeps 40 cm from the wall in unseen rooms";

TEST(WallFollowAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  for (const course::Check& c : rubric.value().checks) {
    points[c.name] = c.points;
    EXPECT_EQ(c.visibility == course::Visibility::Hidden, c.name == kUnseenRound || c.name == kUnseenKeeps) << c.name;
    if (c.visibility == course::Visibility::Hidden) {
      ASSERT_TRUE(c.generated.has_value()) << c.name;
      EXPECT_EQ(c.generated->kind, worlds::WorldKind::Outline) << c.name;
      EXPECT_EQ(c.generated->secret, 2) << c.name;
      EXPECT_EQ(c.drawName(), kUnseenRound) << c.name;  // "the same two rooms"
    }
  }
  EXPECT_EQ(points, (Scores{{kRound, 4}, {kKeeps, 4}, {kUnseenRound, 2}, {kUnseenKeeps, 2}}));
}

// The waypoints a to f of every world, visible or of the hidden family, lie on the path of a robot
// that keeps 40 cm between its rim and the wall: its centre 63 cm from the nearest wall. The robot
// starts 60 or 90 cm from the wall on its right (55 to 65 cm from its rim in the family).
TEST(WallFollowAssignment, WaypointsLieOnTheFollowersPath) {
  std::vector<std::pair<std::string, Result<worlds::WorldDef>>> all;
  for (const char* file : {"worlds/l_room.toml", "worlds/notched_block.toml"})
    all.emplace_back(file, worlds::loadWorld(assignmentFile(kAssignment, file)));
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    all.emplace_back("outline " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::Outline, seed));
  for (const auto& [file, world] : all) {
    ASSERT_TRUE(world) << world.error();
    const std::vector<worlds::WallDef>& walls = world->walls;  // clang 15 cannot capture a structured binding in a lambda
    auto nearestWall = [&](const Point2& p) {
      double d = 1e9;
      for (const worlds::WallDef& w : walls) d = std::min(d, worlds::distanceToWall(p, w));
      return d;
    };
    for (const char* name : {"a", "b", "c", "d", "e", "f"}) {
      std::optional<Point2> p = worlds::findPoint(*world, name);
      ASSERT_TRUE(p.has_value()) << file << " has no " << name;
      EXPECT_NEAR(nearestWall(*p), 0.63, 0.005) << file << ": " << name;
    }
    // The point 60 or 90 cm to the right of the robot's rim, square to its heading, is on a wall.
    ASSERT_EQ(world->robots.size(), 1u) << file;
    const worlds::RobotDef& robot = world->robots[0];
    const Vec2 right(std::sin(robot.start.heading), -std::cos(robot.start.heading));
    auto onAWall = [&](double gap) { return nearestWall(robot.start.position + (robot.radius + gap) * right) < 1e-9; };
    if (file.starts_with("worlds/")) {
      EXPECT_TRUE(onAWall(0.6) || onAWall(0.9)) << file;
    } else {
      EXPECT_NEAR(nearestWall(robot.start.position) - robot.radius, 0.60, 0.05) << file;
    }
  }
}

TEST(WallFollowAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 4}, {kKeeps, 4}, {kUnseenRound, 2}, {kUnseenKeeps, 2}}));
  EXPECT_EQ(g.score(), g.maxScore());
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(reasons(g, c.name), "") << c.name;
}

// The paper's rerror used the simplest way, turning in proportion to it: once it turns towards the
// wall its right sonar hears nothing, so it turns on, and circles by the wall for the whole run.
TEST(WallFollowAssignment, StarterScoresNothing) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 0}, {kKeeps, 0}, {kUnseenRound, 0}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/l_room.toml, seed 1: never came within 0.30 m of a (closest 3.43 m"));
  EXPECT_THAT(reasons(g, kKeeps), HasSubstr("kept 0.40 ± 0.06 m from the wall on its right for 0% of the time after 10.0 s; 80% required"));
}

// The reference follower mirrored: 40 cm from the wall on its LEFT. It keeps its distance all the
// way, but from the wrong wall: it goes round the L-shaped room the other way (past a, then never
// b) and round the outer wall instead of the block, and "keeps 40 cm" asks for the wall on the right.
TEST(WallFollowAssignment, FollowingTheLeftWallKeepsItsDistanceTheWrongWayRound) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "left_wall.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 0}, {kKeeps, 0}, {kUnseenRound, 0}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(reasons(g, kKeeps), HasSubstr("in worlds/l_room.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for "));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/l_room.toml, seed 1: reached a at 48.1 s, never came within 0.30 m of b after that"));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/notched_block.toml, seed 1: never came within 0.30 m of a (closest 1.86 m"));
  EXPECT_EQ(failedIn(g, kUnseenRound), "generated outline, hidden world 1\ngenerated outline, hidden world 2\n");
  EXPECT_THAT(judged(g, kUnseenRound), HasSubstr("in hidden world 2: reached a at 58.5 s, never came within 0.30 m of b after that"));
}

// The reference follower with example 6's setpoint, 25 cm: never at 40 cm. It goes round the
// L-shaped room and the unseen rooms (their waypoints allow 30 cm), but so close to the wall it
// loses its way in the notch.
TEST(WallFollowAssignment, TooCloseGoesRoundButNeverAtTheSetpoint) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "too_close.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 2}, {kKeeps, 0}, {kUnseenRound, 2}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(reasons(g, kKeeps),
              HasSubstr("in worlds/l_room.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for 0% of the time after 10.0 s"));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/notched_block.toml, seed 1: reached a at 13.7 s, never came within 0.30 m of b after that"));
  EXPECT_EQ(failedIn(g, kUnseenKeeps), "generated outline, hidden world 1\ngenerated outline, hidden world 2\n");
}

// A bang-bang follower: full turn left when the right sonar reads under 40 cm, full turn right
// when over. It weaves (within 6 cm of 40 cm a fifth of the time) and, never slowing down, runs
// into the wall ahead at a concave corner.
TEST(WallFollowAssignment, BangBangOscillatesAndBumpsAtCorners) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "oscillates.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 0}, {kKeeps, 0}, {kUnseenRound, 0}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/l_room.toml, seed 1: touched a wall at 36.9 s at (3.4, 5.8)"));
  EXPECT_THAT(reasons(g, kKeeps), HasSubstr("in worlds/l_room.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for 23% of the time"));
  EXPECT_THAT(reasons(g, kKeeps),
              HasSubstr("in worlds/notched_block.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for 18% of the time"));
  EXPECT_THAT(judged(g, kUnseenRound), HasSubstr("touched a wall at 14.0 s"));
}

// Like example 2, it stops when the wall on its right ends: at the first convex corner, by the
// wall and at the right distance. Standing there keeps 40 cm from the wall, but not "as it goes":
// it has seen too little of the floor.
TEST(WallFollowAssignment, StoppingAtTheEndOfTheWallDoesNotGoRound) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "stops_at_end.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 0}, {kKeeps, 0}, {kUnseenRound, 0}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(
      reasons(g, kRound),
      HasSubstr(
          "in worlds/l_room.toml, seed 1: reached a at 9.7 s, reached b at 17.4 s, reached c at 25.3 s, never came within 0.30 m of d after that"));
  EXPECT_THAT(reasons(g, kKeeps),
              HasSubstr("in worlds/l_room.toml, seed 1: covered 12% of the floor it could reach (20 of 168 cells of 0.50 m); 15% required"));
  EXPECT_THAT(reasons(g, kKeeps), HasSubstr("in worlds/notched_block.toml, seed 1: covered 2% of the floor it could reach"));
  EXPECT_THAT(judged(g, kUnseenKeeps),
              HasSubstr("in hidden world 2: covered 8% of the floor it could reach (13 of 165 cells of 0.50 m); 15% required"));
}

// Example 2 copied as it is follows the wall on its LEFT, 50 cm away, and stops when that wall
// ends. In the L-shaped room the left wall is far: it stops at once. By the block it follows the
// outer wall: not the block's waypoints, and 50 cm is not 40 ± 6 cm.
TEST(WallFollowAssignment, Example2AsItIsFollowsTheWrongWall) {
  course::Grade g = gradeFile(kAssignment, example("02_wall_follower.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kRound, 0}, {kKeeps, 0}, {kUnseenRound, 0}, {kUnseenKeeps, 0}}));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/l_room.toml, seed 1: never came within 0.30 m of a (closest 4.01 m, at 0.0 s)"));
  EXPECT_THAT(reasons(g, kRound), HasSubstr("in worlds/notched_block.toml, seed 1: never came within 0.30 m of a (closest 1.75 m"));
  EXPECT_THAT(reasons(g, kKeeps),
              HasSubstr("in worlds/l_room.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for 0% of the time after 10.0 s"));
  EXPECT_THAT(reasons(g, kKeeps),
              HasSubstr("in worlds/notched_block.toml, seed 1: kept 0.40 ± 0.06 m from the wall on its right for 0% of the time"));
}

}  // namespace
}  // namespace frob::testing
