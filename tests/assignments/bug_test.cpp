// The bug assignment graded as CI grades it, hidden checks included (test secret): the reference
// solution gets full marks, the starter nothing, and each typical wrong submission of
// tests/assignments/bug/ exactly the partial score it deserves, failing the checks it should with
// a reason a student can act on. Course example 6 (the paper's BUG), copied as it is or with its
// goal corrected, does not pass: it goes all the way round every obstacle and nothing limits how
// long it goes round.
#include "frob/worlds/generate.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

#include <fstream>
#include <sstream>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "bug";
const std::string kReaches = "reaches the goal";
const std::string kBound = "within the BUG1 bound";
const std::string kHidden = "hidden fields";
const std::string kHiddenBound = "hidden fields, within the BUG1 bound";

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(BugAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  for (const course::Check& c : rubric.value().checks) points[c.name] = c.points;
  EXPECT_EQ(points, (Scores{{kReaches, 5}, {kBound, 3}, {kHidden, 2}, {kHiddenBound, 2}}));
  for (const course::Check& hidden : {rubric.value().checks[2], rubric.value().checks[3]}) {
    EXPECT_EQ(hidden.visibility, course::Visibility::Hidden);
    ASSERT_TRUE(hidden.generated.has_value());
    EXPECT_EQ(hidden.generated->kind, worlds::WorldKind::Obstacles);
    EXPECT_EQ(hidden.generated->secret, 4);
  }
  // "The same run", "the same four runs": the bound is judged where the goal is.
  EXPECT_EQ(rubric.value().checks[1].seeds, rubric.value().checks[0].seeds);
  EXPECT_EQ(rubric.value().checks[3].drawName(), kHidden);
}

// The visible worlds are generated obstacle fields, exactly as `frob world generate obstacles
// --seed N` writes them (plus one comment line saying so), so the handout's promises hold for them:
// start (1.5, 1.5), goal (13.5, 13.5), a way between.
TEST(BugAssignment, VisibleWorldsAreGeneratedFields) {
  for (const auto& [file, seed] : {std::pair{"worlds/trap.toml", 52}, std::pair{"worlds/field.toml", 19}}) {
    Result<worlds::WorldDef> made = worlds::generateWorld(worlds::WorldKind::Obstacles, seed);
    ASSERT_TRUE(made.ok()) << made.error();
    std::string text = readFile(assignmentFile(kAssignment, file));
    const std::string note = "# frob world generate obstacles --seed " + std::to_string(seed) + " --out assignments/bug/" + file + "\n";
    const std::size_t at = text.find(note);
    ASSERT_NE(at, std::string::npos) << file;
    text.erase(at, note.size());
    EXPECT_EQ(text, worlds::toToml(made.value())) << file;
  }
}

TEST(BugAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  ASSERT_EQ(g.checks.size(), 4u);
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(c.score, c.points) << c.name << ":\n" << c.output();
  EXPECT_EQ(g.score(), 12.0);
}

// Two fields the solution used to fail (with these run seeds), each for its own reason: round a
// small block its follower swung wide, heard no wall, and never let the leave rule fire (nor came
// back near the point it had found nearest the goal); at a block's corner, met at a slant, it
// reversed for less time than its wheels take to stop and turned on the spot against the block,
// pressing its bumpers for more than the bound check's 3 s in all.
TEST(BugAssignment, SolutionLeavesASmallBlockAndBacksOffACornerItBumps) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "bug_test_fields";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "rubric.toml") << R"(title = "two fields"
seconds = 120
[[check]]
name = "small block"
points = 1
generated = { kind = "obstacles", seeds = [384947559] }
seeds = [207198145]
goal = { within = 0.3 }
collisions = { max = 4 }
[[check]]
name = "corner"
points = 1
generated = { kind = "obstacles", seeds = [630629015] }
seeds = [27195284]
bug1_bound = { point = "goal", within = 0.3 }
collisions = { max = 8, seconds = 3 }
)";
  Result<course::Rubric> rubric = course::loadRubric(dir / "rubric.toml");
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  course::GradeDef def{.rubric = rubric.value(), .assignment = kAssignment, .secret = kTestSecret};
  def.compiler.cacheDir = FROB_TEST_CACHE_DIR;
  course::Grade g = course::grade(def, assignmentFile(kAssignment, "solution.cpp"));
  EXPECT_EQ(scores(g), (Scores{{"small block", 1}, {"corner", 1}})) << reasons(g, "small block") << reasons(g, "corner");
}

// The starter drives at the goal and stops at the first obstacle: it compiles and runs, and earns
// nothing yet.
TEST(BugAssignment, StarterScoresNothing) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 0}, {kBound, 0}, {kHidden, 0}, {kHiddenBound, 0}}));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/trap.toml, seed 872466220: never came within 0.30 m of goal"));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/field.toml, seed 872466220: never came within 0.30 m of goal"));
  EXPECT_THAT(reasons(g, kBound), HasSubstr("so its path cannot be measured"));
  EXPECT_THAT(judged(g, kHidden), HasSubstr("never came within 0.30 m of goal"));
}

// Without taskCatch, the first error ends the controller. In the trap field going round takes
// longer than its 30 s limit, and nothing restarts BUG; in the other fields no leg fails and it
// does as well as the solution.
TEST(BugAssignment, ForgettingTaskCatchStopsAtTheFirstError) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "no_task_catch.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 2.5}, {kBound, 3}, {kHidden, 2}, {kHiddenBound, 2}}));
  const std::string why = reasons(g, kReaches);
  EXPECT_THAT(why, HasSubstr("in worlds/trap.toml, seed 872466220: the controller failed"));
  EXPECT_THAT(why, HasSubstr("going round one obstacle took more than 30 s"));
  EXPECT_THAT(why, Not(HasSubstr("field.toml")));
}

// Example 06 pasted onto the starter (goal corrected): the paper's BUG goes all the way round every
// obstacle and on to the closest point. In the trap field that takes longer than the run; in the
// open field and one of the hidden ones it arrives, past the BUG1 bound, and in another after the
// 100 s the hidden check allows.
TEST(BugAssignment, ThePapersBugCirclesForeverAndDrivesPastTheBound) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "circles_forever.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 2.5}, {kBound, 0}, {kHidden, 0.5}, {kHiddenBound, 0}}));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/trap.toml, seed 872466220: never came within 0.30 m of goal"));
  EXPECT_THAT(reasons(g, kBound), HasSubstr("in worlds/field.toml, seed 872466220: drove 31.28 m to goal; the BUG1 bound is 30.88 m"));
  EXPECT_THAT(judged(g, kHidden), HasSubstr("in hidden world 1: reached goal at 101.3 s; allowed 100 s"));
  EXPECT_THAT(judged(g, kHidden), HasSubstr("in hidden world 2: never came within 0.30 m of goal"));
  EXPECT_THAT(judged(g, kHiddenBound), HasSubstr("the BUG1 bound is"));
}

// No BUG at all: it steers at the goal by odometry and pushes along whatever is in the way. In the
// open field it slides round two obstacles to the goal on a path well inside the BUG1 bound, but
// every second of pushing counts as a collision (before, each push was one, and it passed "reaches
// the goal"): a bump at a corner the sonars cannot hear is brief, pushing along an obstacle is not.
// No hidden field lets it through.
TEST(BugAssignment, SlidingAlongObstaclesIsNoPathRoundThem) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "slides_along.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 0}, {kBound, 0}, {kHidden, 0}, {kHiddenBound, 0}}));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/field.toml, seed 872466220: touched a round obstacle at"));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("4 allowed)"));
}

// No sensing: round the field's edge by odometry. The spurs beside the start cut both ways along
// the walls, so it reaches no goal (before the spurs, it reached every one).
TEST(BugAssignment, ABlindDriveAlongTheWallsReachesNoGoal) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "drives_along_the_walls.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 0}, {kBound, 0}, {kHidden, 0}, {kHiddenBound, 0}}));
  EXPECT_THAT(judged(g, kHidden), HasSubstr("in hidden world 1: never came within 0.30 m of goal"));
}

// Course example 6 copied as it is drives to the reference world's goal (13, 13), not the
// generated fields' (13.5, 13.5): it gets nothing.
TEST(BugAssignment, CopiedExampleSixGetsNothing) {
  course::Grade g = gradeFile(kAssignment, example("06_bug.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kReaches, 0}, {kBound, 0}, {kHidden, 0}, {kHiddenBound, 0}}));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/field.toml, seed 872466220: never came within 0.30 m of goal (closest 5.76 m"));
  EXPECT_THAT(reasons(g, kBound), HasSubstr("so its path cannot be measured"));
}

// Example 6 with its goal corrected to (13.5, 13.5) is still not an answer: it crosses neither
// visible field in time, and in every hidden field it fails the BUG1 bound (it reaches the goal in
// time in one).
TEST(BugAssignment, ExampleSixWithTheGoalCorrectedDoesNotPass) {
  std::string source = readFile(example("06_bug.cpp"));
  const std::string goal = "Point2 goal{13, 13};";
  const std::size_t at = source.find(goal);
  ASSERT_NE(at, std::string::npos) << "example 06 no longer sets its goal with '" << goal << "'";
  source.replace(at, goal.size(), "Point2 goal{13.5, 13.5};");
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "bug_test_example06";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "example06_goal_corrected.cpp") << source;

  course::Grade g = gradeFile(kAssignment, dir / "example06_goal_corrected.cpp");
  EXPECT_EQ(scores(g), (Scores{{kReaches, 0}, {kBound, 0}, {kHidden, 0.5}, {kHiddenBound, 0}}));
  EXPECT_THAT(reasons(g, kReaches), HasSubstr("in worlds/trap.toml, seed 872466220: never came within 0.30 m of goal"));
  EXPECT_THAT(reasons(g, kBound),
              HasSubstr("in worlds/field.toml, seed 872466220: never came within 0.30 m of goal, so its path cannot be measured"));
  for (const char* world : {"hidden world 1", "hidden world 2", "hidden world 3", "hidden world 4"}) {
    EXPECT_THAT(judged(g, kHiddenBound), HasSubstr(world));
  }
}

}  // namespace
}  // namespace frob::testing
