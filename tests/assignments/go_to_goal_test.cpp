// The go_to_goal assignment graded as CI grades it, hidden checks included (test secret): the
// reference solution gets full marks, the starter nothing, and each typical wrong submission of
// tests/assignments/go_to_goal/ exactly the partial score it deserves, failing the checks it should
// with a reason a student can act on. Course examples 4 (driveTo to one point) and 6 (BUG), copied,
// do not pass.
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "go_to_goal";
const std::string kInOrder = "visits the waypoints in order";
const std::string kInTime = "within the time limit";
const std::string kSofa = "goes round the sofa without touching anything";
const std::string kOtherRooms = "other rooms, other furniture";

TEST(GoToGoalAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  for (const course::Check& c : rubric.value().checks) points[c.name] = c.points;
  EXPECT_EQ(points, (Scores{{kInOrder, 3}, {kInTime, 2}, {kSofa, 2}, {kOtherRooms, 3}}));
  const course::Check& hidden = rubric.value().checks.back();
  EXPECT_EQ(hidden.name, kOtherRooms);
  EXPECT_EQ(hidden.visibility, course::Visibility::Hidden);
  ASSERT_TRUE(hidden.generated.has_value());
  EXPECT_EQ(hidden.generated->kind, worlds::WorldKind::Lounge);
  EXPECT_EQ(hidden.generated->secret, 2);
}

// The handout gives the waypoints' coordinates once: every world, visible or of the hidden family,
// has them there, and starts the robot within 0.2 m of (1.5, 1.5), heading within 20 degrees of east.
TEST(GoToGoalAssignment, EveryWorldHasTheHandoutsWaypointsAndStart) {
  const std::map<std::string, Point2> handout = {{"wp1", {3.0, 2.5}}, {"wp2", {3.5, 7.5}}, {"wp3", {9.0, 7.0}}, {"wp4", {8.5, 2.5}}};
  std::vector<std::pair<std::string, Result<worlds::WorldDef>>> all;
  all.emplace_back("worlds/lounge.toml", worlds::loadWorld(assignmentFile(kAssignment, "worlds/lounge.toml")));
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    all.emplace_back("lounge " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::Lounge, seed));
  for (const auto& [file, world] : all) {
    ASSERT_TRUE(world) << world.error();
    for (const auto& [name, at] : handout) {
      std::optional<Point2> p = worlds::findPoint(*world, name);
      ASSERT_TRUE(p.has_value()) << file << " has no " << name;
      EXPECT_EQ(*p, at) << file << ": " << name;
    }
    ASSERT_EQ(world->robots.size(), 1u) << file;
    EXPECT_LE((world->robots[0].start.position - Point2(1.5, 1.5)).cwiseAbs().maxCoeff(), 0.2) << file;
    EXPECT_LE(std::abs(world->robots[0].start.heading), 20 * pi / 180 + 1e-9) << file;
  }
}

TEST(GoToGoalAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  ASSERT_EQ(g.checks.size(), 4u);
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(c.score, c.points) << c.name << ":\n" << c.output();
  EXPECT_EQ(g.score(), 10.0);
}

// The starter drives to wp1 and stops there: it compiles and runs, and earns nothing yet.
TEST(GoToGoalAssignment, StarterScoresNothing) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 0}, {kInTime, 0}, {kSofa, 0}, {kOtherRooms, 0}}));
  EXPECT_THAT(reasons(g, kInOrder), HasSubstr("reached wp1 at"));
  EXPECT_THAT(reasons(g, kInOrder), HasSubstr("never came within 0.20 m of wp2"));
}

// Example 4 copied with the handout's waypoints: it gives up at the first obstacle (the sofa).
TEST(GoToGoalAssignment, CopiedExample4GivesUpAtTheSofa) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "copied_example.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 0}, {kInTime, 0}, {kSofa, 0}, {kOtherRooms, 0}}));
  for (const std::string& check : {kInOrder, kInTime, kSofa}) {
    EXPECT_THAT(reasons(g, check), AllOf(HasSubstr("reached wp1 at "), HasSubstr("s, never came within 0.20 m of wp2"))) << check;
  }
  EXPECT_THAT(judged(g, kOtherRooms), HasSubstr("in hidden world 1: reached wp1 at 4.4 s, never came within 0.20 m of wp2"));
}

// Example 4 itself (two points of the empty room) does not come near the waypoints at all.
TEST(GoToGoalAssignment, Example4AsItIsScoresNothing) {
  course::Grade g = gradeFile(kAssignment, example("04_drive_to.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 0}, {kInTime, 0}, {kSofa, 0}, {kOtherRooms, 0}}));
  EXPECT_THAT(reasons(g, kInOrder), HasSubstr("never came within 0.20 m of wp1"));
}

// Example 6's BUG, once per waypoint: in order and untouched, but BUG circles each obstacle once
// before it leaves it, which takes some 95 s for a round the time limit allows 75 s for.
TEST(GoToGoalAssignment, CopiedExample6IsTooSlow) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "bug_per_waypoint.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 3}, {kInTime, 0}, {kSofa, 2}, {kOtherRooms, 0}}));
  EXPECT_THAT(reasons(g, kInTime), HasSubstr("reached wp3 at 63.8 s, never came within 0.20 m of wp4"));
  EXPECT_THAT(judged(g, kOtherRooms), HasSubstr("never came within 0.20 m of wp4"));
}

// After wp1 it goes round the room the wrong way: wp4, wp3, then wp2.
TEST(GoToGoalAssignment, WrongOrderFailsEveryCheck) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "wrong_order.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 0}, {kInTime, 0}, {kSofa, 0}, {kOtherRooms, 0}}));
  EXPECT_THAT(reasons(g, kInOrder), HasSubstr("reached wp1 at 4.7 s, reached wp2 at 53.0 s, never came within 0.20 m of wp3 after that"));
  EXPECT_THAT(reasons(g, kSofa), HasSubstr("never came within 0.20 m of wp2 after that"));
}

// The solution at half speed: everything right but the time limit (the round takes about 93 s).
TEST(GoToGoalAssignment, TooSlowMissesTheTimeLimit) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "too_slow.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 3}, {kInTime, 0}, {kSofa, 2}, {kOtherRooms, 0}}));
  EXPECT_THAT(reasons(g, kInTime), HasSubstr("reached wp3 at 62.9 s, never came within 0.20 m of wp4"));
}

// A route worked out by hand round the lounge's furniture: full marks in the lounge, and it runs
// into the furniture of both hidden rooms, and pushes on (a second collision). This is what the
// hidden check is for.
TEST(GoToGoalAssignment, HardCodedRouteFailsOnlyTheHiddenRooms) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "hard_coded_route.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kInOrder, 3}, {kInTime, 2}, {kSofa, 2}, {kOtherRooms, 0}}));
  EXPECT_EQ(failedIn(g, kOtherRooms), "generated lounge, hidden world 1\ngenerated lounge, hidden world 2\n");
  EXPECT_THAT(judged(g, kOtherRooms), HasSubstr("in hidden world 1: touched a round obstacle at 26.5 s at (6.2, 6.4) (3 collisions; 0 allowed)\n"));
  EXPECT_THAT(judged(g, kOtherRooms), HasSubstr("in hidden world 2: touched a round obstacle at 25.6 s at (5.7, 6.3) (3 collisions; 0 allowed)\n"));
}

}  // namespace
}  // namespace frob::testing
