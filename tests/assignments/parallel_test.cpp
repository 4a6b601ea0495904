// The parallel assignment graded as CI grades it, hidden checks included (test secret): the
// reference solution gets full marks, the starter only the patrol's points, and each typical wrong
// submission of tests/assignments/parallel/ exactly the partial score it deserves, failing the
// checks it should with a reason a student can act on. Course example 7 (withTask with a trip
// meter), copied, does not pass: the key, the bumpers and the reason change what must happen.
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "parallel";
const std::string kPatrol = "patrols p1, p2, p3, p4 and back to p1";
const std::string kKey = "stops at once when s is pressed";
const std::string kBump = "stops at the first bump";
const std::string kBudget = "stops when the 20 m budget is used";
const std::string kOtherKeys = "other keys do not stop it";
const std::string kOtherBox = "a box elsewhere in the aisles";

const char* const kStillMoving = "m/s at the end; it should stop";  // the speed: 0.6 m/s, give or take the slip
const char* const kMovedAfterTheKey = "after the key s was pressed; it should stop within 2 s (below 0.02 m/s)";

TEST(ParallelAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  int hidden = 0;
  for (const course::Check& c : rubric.value().checks) {
    points[c.name] = c.points;
    if (c.visibility == course::Visibility::Hidden) {
      ++hidden;
      ASSERT_TRUE(c.generated.has_value()) << c.name;
      EXPECT_EQ(c.generated->kind, c.name == kOtherKeys ? worlds::WorldKind::WarehouseKeys : worlds::WorldKind::WarehouseBox) << c.name;
      EXPECT_EQ(c.generated->secret, 2) << c.name;
    }
  }
  EXPECT_EQ(points, (Scores{{kPatrol, 2}, {kKey, 2}, {kBump, 2}, {kBudget, 2}, {kOtherKeys, 1}, {kOtherBox, 1}}));
  EXPECT_EQ(hidden, 2);
}

// The handout gives the route's coordinates once: every world, visible or of the hidden families,
// has them there, and starts the robot at (1, 1) (within 0.15 m in the families).
TEST(ParallelAssignment, EveryWorldHasTheHandoutsRouteAndStart) {
  const std::map<std::string, Point2> handout = {{"p1", {1.5, 1.5}}, {"p2", {6.5, 1.5}}, {"p3", {6.5, 4.5}}, {"p4", {1.5, 4.5}}};
  std::vector<std::pair<std::string, Result<worlds::WorldDef>>> all;
  for (const char* file : {"worlds/warehouse.toml", "worlds/warehouse_key.toml", "worlds/warehouse_box.toml"}) {
    all.emplace_back(file, worlds::loadWorld(assignmentFile(kAssignment, file)));
  }
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    all.emplace_back("warehouse_keys " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::WarehouseKeys, seed));
    all.emplace_back("warehouse_box " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::WarehouseBox, seed));
  }
  for (const auto& [file, world] : all) {
    ASSERT_TRUE(world) << world.error();
    for (const auto& [name, at] : handout) {
      std::optional<Point2> p = worlds::findPoint(*world, name);
      ASSERT_TRUE(p.has_value()) << file << " has no " << name;
      EXPECT_EQ(*p, at) << file << ": " << name;
    }
    ASSERT_EQ(world->robots.size(), 1u) << file;
    EXPECT_LE((world->robots[0].start.position - Point2(1.0, 1.0)).cwiseAbs().maxCoeff(), file.starts_with("worlds/") ? 0.0 : 0.15) << file;
  }
}

TEST(ParallelAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  ASSERT_EQ(g.checks.size(), 6u);
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(c.score, c.points) << c.name << ":\n" << c.output();
  EXPECT_EQ(g.score(), 10.0);
}

// The starter patrols for ever: the patrol's points, nothing else.
TEST(ParallelAssignment, StarterOnlyPatrols) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 2}, {kKey, 0}, {kBump, 0}, {kBudget, 0}, {kOtherKeys, 0}, {kOtherBox, 0}}));
  for (const std::string& check : {kKey, kBudget}) EXPECT_THAT(reasons(g, check), HasSubstr(kStillMoving)) << check;
  EXPECT_THAT(reasons(g, kBump), HasSubstr("collisions; 1 allowed)"));  // it pushes the box on: a collision for every second of it
  EXPECT_THAT(judged(g, kOtherKeys), HasSubstr(kMovedAfterTheKey));
  EXPECT_THAT(judged(g, kOtherBox), HasSubstr("its task never returned a value"));
}

// Example 7 copied, with the patrol as its driver and the budget as its trip: it patrols and stops
// after 20 m, but a key press and a bump change nothing, and it reports no reason.
TEST(ParallelAssignment, CopiedExample7IgnoresKeyAndBumpersAndGivesNoReason) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "copied_example.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 2}, {kKey, 0}, {kBump, 0}, {kBudget, 0}, {kOtherKeys, 0}, {kOtherBox, 0}}));
  EXPECT_THAT(reasons(g, kKey), HasSubstr(kStillMoving));
  EXPECT_THAT(reasons(g, kBump), HasSubstr("collisions; 1 allowed)"));
  EXPECT_THAT(reasons(g, kBudget), HasSubstr("not budget (reported by the controller)"));
}

// Example 7 as it is wanders the room: it never comes near the route.
TEST(ParallelAssignment, Example7AsItIsScoresNothing) {
  course::Grade g = gradeFile(kAssignment, example("07_with_task.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 0}, {kKey, 0}, {kBump, 0}, {kBudget, 0}, {kOtherKeys, 0}, {kOtherBox, 0}}));
  EXPECT_THAT(reasons(g, kPatrol), HasSubstr("never came within 0.20 m of p1"));
}

// The watcher does not watch the keyboard: the operator cannot stop it.
TEST(ParallelAssignment, IgnoringTheKeyFailsTheKeyChecks) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "ignores_key.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 2}, {kKey, 0}, {kBump, 2}, {kBudget, 2}, {kOtherKeys, 0}, {kOtherBox, 1}}));
  EXPECT_THAT(reasons(g, kKey), HasSubstr(kStillMoving));
  EXPECT_THAT(judged(g, kOtherKeys), HasSubstr(kMovedAfterTheKey));
}

// Any key stops it: right in the visible key world, wrong when another key is pressed before s: in
// the hidden warehouses one comes before it has reached p1, and it stops there.
TEST(ParallelAssignment, StoppingOnAnyKeyFailsTheOtherKeysCheck) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "stops_on_any_key.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 2}, {kKey, 2}, {kBump, 2}, {kBudget, 2}, {kOtherKeys, 0}, {kOtherBox, 1}}));
  EXPECT_THAT(judged(g, kOtherKeys), HasSubstr("in hidden world 1: never came within 0.20 m of p1 (closest 0.43 m, at 2.2 s)"));
}

// The watcher does not watch the bumpers: the robot pushes past the box and patrols on.
TEST(ParallelAssignment, IgnoringTheBumpersFailsTheBoxChecks) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "ignores_bumper.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 2}, {kKey, 2}, {kBump, 0}, {kBudget, 2}, {kOtherKeys, 1}, {kOtherBox, 0}}));
  EXPECT_THAT(reasons(g, kBump), HasSubstr("collisions; 1 allowed)"));  // it pushes the box on: a collision for every second of it
  EXPECT_THAT(judged(g, kOtherBox), HasSubstr("in hidden world 1: its task never returned a value"));
}

// withTask without withExit: the watcher ends as it should, but nothing ends the patrol.
// Its trip label reads the watcher's output after the watcher ended. Pictures are sampled in every
// run, graded ones too, so the run fails the moment the watcher ends (before, only a filmed run did,
// and the graded one went on moving: the patrol check passed and the others read "still moving").
TEST(ParallelAssignment, AWatcherWhoseEndIsIgnoredStopsNothing) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "patrol_never_ends.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kPatrol, 0}, {kKey, 0}, {kBump, 0}, {kBudget, 0}, {kOtherKeys, 0}, {kOtherBox, 0}}));
  for (const std::string& check : {kPatrol, kKey, kBump, kBudget, kOtherKeys, kOtherBox}) {
    EXPECT_THAT(judged(g, check), HasSubstr("withTask: task 'watcher' ended at t = ")) << check;
    EXPECT_THAT(judged(g, check), HasSubstr("a task's output exists only while it runs")) << check;
  }
}

}  // namespace
}  // namespace frob::testing
