// The multi_robot assignment graded as CI grades it, hidden checks included (test secret): the
// reference solution gets full marks, the starter nothing, and each typical wrong submission of
// tests/assignments/multi_robot/ exactly the partial score it deserves, failing the checks it
// should with a reason a student can act on. Course example 4 (driveTo to two fixed points),
// copied, gets nothing.
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "multi_robot";
const std::string kGoals = "every robot reaches its goal";
const std::string kApart = "crosses the middle without touching anyone";
const std::string kOthers = "other arrangements";

TEST(MultiRobotAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  for (const course::Check& c : rubric.value().checks) points[c.name] = c.points;
  EXPECT_EQ(points, (Scores{{kGoals, 4}, {kApart, 4}, {kOthers, 6}}));
  const course::Check& hidden = rubric.value().checks.back();
  EXPECT_EQ(hidden.name, kOthers);
  EXPECT_EQ(hidden.visibility, course::Visibility::Hidden);
  ASSERT_TRUE(hidden.generated.has_value());
  EXPECT_EQ(hidden.generated->kind, worlds::WorldKind::Crossing);
  EXPECT_EQ(hidden.generated->secret, 4);
  EXPECT_EQ(rubric.value().checks[1].drawName(), kGoals);  // "the same runs"
}

// The handout's promises, which let a controller that never sees the world find its goal: every
// world is a 10 x 10 m arena with 2 to 4 robots, at least 1 m from the walls and from each other,
// and each robot's goal_<name> is the point opposite its start through the centre (5, 5), which is
// named "centre".
TEST(MultiRobotAssignment, EveryGoalIsOppositeItsRobotsStart) {
  const Point2 centre(5.0, 5.0);
  std::vector<std::pair<std::string, Result<worlds::WorldDef>>> all;
  for (const char* file : {"worlds/swap.toml", "worlds/corners.toml"}) all.emplace_back(file, worlds::loadWorld(assignmentFile(kAssignment, file)));
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    all.emplace_back("crossing " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::Crossing, seed));
  for (const auto& [file, world] : all) {
    ASSERT_TRUE(world) << world.error();
    EXPECT_EQ(world->size, Vec2(10.0, 10.0)) << file;
    EXPECT_GE(world->robots.size(), 2u) << file;
    EXPECT_LE(world->robots.size(), 4u) << file;
    EXPECT_EQ(worlds::findPoint(*world, "centre"), std::optional<Point2>(centre)) << file;
    for (const worlds::RobotDef& r : world->robots) {
      const Point2 p = r.start.position;
      EXPECT_TRUE(p.x() >= 1.0 && p.x() <= 9.0 && p.y() >= 1.0 && p.y() <= 9.0) << file << ": " << r.name << " is near a wall";
      for (const worlds::RobotDef& other : world->robots) {
        if (&other != &r) EXPECT_GE((other.start.position - p).norm(), 1.0) << file << ": " << r.name << " and " << other.name;
      }
      std::optional<Point2> goal = worlds::findPoint(*world, "goal_" + r.name);
      ASSERT_TRUE(goal.has_value()) << file << " has no goal_" << r.name;
      EXPECT_LT((*goal - (centre + (centre - r.start.position))).norm(), 1e-9) << file << ": goal_" << r.name;
    }
  }
}

TEST(MultiRobotAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  ASSERT_EQ(g.checks.size(), 3u);
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(c.score, c.points) << c.name << ":\n" << c.output();
  EXPECT_EQ(g.score(), 14.0);
}

// The starter sends every robot to the centre: they meet there and touch, and nobody reaches a goal.
TEST(MultiRobotAssignment, StarterScoresNothing) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kGoals, 0}, {kApart, 0}, {kOthers, 0}}));
  EXPECT_THAT(reasons(g, kGoals), HasSubstr("in worlds/swap.toml, seed 673553025: ada never came within 0.30 m of goal_ada"));
  EXPECT_THAT(reasons(g, kApart), HasSubstr("in worlds/swap.toml, seed 673553025: ada and bob touched at"));
  EXPECT_THAT(reasons(g, kApart), HasSubstr("in worlds/corners.toml, seed 673553025: ada and bob touched at"));
}

// Robots that never look out for each other meet in the middle and shove past each other (their
// wheels slip, so two head-on never push exactly against each other): they arrive, but they touched.
TEST(MultiRobotAssignment, RobotsThatDriveStraightCollide) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "straight.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kGoals, 4}, {kApart, 0}, {kOthers, 0}}));
  EXPECT_EQ(reasons(g, kGoals), "");
  EXPECT_THAT(reasons(g, kApart), HasSubstr("in worlds/swap.toml, seed 673553025: ada and bob touched at"));
  EXPECT_THAT(reasons(g, kApart), HasSubstr("in worlds/corners.toml, seed 673553025: ada and bob touched at"));
  EXPECT_THAT(failedIn(g, kOthers), HasSubstr("generated crossing, hidden world 1\n"));
  EXPECT_THAT(judged(g, kOthers), HasSubstr("touched at"));
}

// "Opposite" read as "the other side" (x mirrored, y kept): right for robots level with the centre
// (the swap world), wrong in the corners, where the robots go to the wrong corner and never cross
// the middle, and wrong for every arrangement of the hidden check.
TEST(MultiRobotAssignment, TheOtherSideIsTheWrongGoal) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "wrong_goal.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kGoals, 2}, {kApart, 2}, {kOthers, 0}}));
  EXPECT_THAT(reasons(g, kGoals), HasSubstr("in worlds/corners.toml, seed 673553025: ada never came within 0.30 m of goal_ada"));
  EXPECT_THAT(reasons(g, kGoals), Not(HasSubstr("swap.toml")));
  EXPECT_THAT(reasons(g, kApart), HasSubstr("in worlds/corners.toml, seed 673553025: ada never came within 1.50 m of centre"));
  EXPECT_THAT(reasons(g, kApart), Not(HasSubstr("touched")));
  EXPECT_THAT(failedIn(g, kOthers), HasSubstr("generated crossing, hidden world 1\n"));
  EXPECT_THAT(judged(g, kOthers), Not(HasSubstr("touched")));
}

// Course example 4 drives every robot to (5, 3) and then (1, 1): nobody's goal.
TEST(MultiRobotAssignment, CopiedExampleFourGetsNothing) {
  course::Grade g = gradeFile(kAssignment, example("04_drive_to.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kGoals, 0}, {kApart, 0}, {kOthers, 0}}));
  EXPECT_THAT(reasons(g, kGoals), HasSubstr("never came within 0.30 m of goal_"));
}

}  // namespace
}  // namespace frob::testing
