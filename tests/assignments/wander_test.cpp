// The wander assignment graded as CI grades it, hidden checks included (test secret): the reference
// solution gets full marks, the starter little, and each typical wrong submission of
// tests/assignments/wander/ exactly the partial score it deserves, failing the checks it should
// with a reason a student can act on. Course example 1 (the paper's runAround), copied as it is,
// does not pass: it stops for the door posts, goes back down the hall and spins there for ever.
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

#include <cmath>

namespace frob::testing {
namespace {

using ::testing::HasSubstr;
using Scores = std::map<std::string, double>;

constexpr const char* kAssignment = "wander";
const std::string kHall = "gets out of the hall";
const std::string kTouch = "never touches anything";
const std::string kExplore = "explores the room";
const std::string kUnseen = "explores unseen rooms without touching anything";

TEST(WanderAssignment, RubricHasTheChecksTheHandoutDescribes) {
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(kAssignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  Scores points;
  for (const course::Check& c : rubric.value().checks) points[c.name] = c.points;
  EXPECT_EQ(points, (Scores{{kHall, 2}, {kTouch, 3}, {kExplore, 3}, {kUnseen, 2}}));
  const course::Check& hidden = rubric.value().checks.back();
  EXPECT_EQ(hidden.name, kUnseen);
  EXPECT_EQ(hidden.visibility, course::Visibility::Hidden);
  ASSERT_TRUE(hidden.generated.has_value());
  EXPECT_EQ(hidden.generated->kind, worlds::WorldKind::FurnishedRoom);
  EXPECT_EQ(hidden.generated->secret, 2);
  // "The three visible checks judge the same four runs": the same worlds, seeds and length.
  for (std::size_t k = 1; k < 3; ++k) {
    const course::Check &first = rubric.value().checks[0], &other = rubric.value().checks[k];
    EXPECT_EQ(other.seeds, first.seeds) << other.name;
    EXPECT_EQ(other.seconds, first.seconds) << other.name;
    ASSERT_EQ(other.worlds.size(), first.worlds.size()) << other.name;
    for (std::size_t w = 0; w < first.worlds.size(); ++w) EXPECT_EQ(other.worlds[w].name, first.worlds[w].name) << other.name;
  }
}

// Every world, visible or of the hidden family, starts the robot alone in a hall and names the
// point 1 m into the room that "gets out of the hall" asks for.
TEST(WanderAssignment, EveryWorldHasOneRobotAndTheRoomPoint) {
  std::vector<std::pair<std::string, Result<worlds::WorldDef>>> all;
  for (const char* file : {"worlds/living_room.toml", "worlds/bedroom.toml"})
    all.emplace_back(file, worlds::loadWorld(assignmentFile(kAssignment, file)));
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    all.emplace_back("furnished_room " + std::to_string(seed), worlds::generateWorld(worlds::WorldKind::FurnishedRoom, seed));
  }
  for (const auto& [file, world] : all) {
    ASSERT_TRUE(world) << world.error();
    ASSERT_EQ(world->robots.size(), 1u) << file;
    std::optional<Point2> room = worlds::findPoint(*world, "room");
    ASSERT_TRUE(room.has_value()) << file;
    // The room point lies 2 to 3 m ahead of the start, beyond the doorway: straight ahead in the
    // handed-out worlds, within 12 degrees in the family (which draws the heading within 10).
    const Pose2& start = world->robots[0].start;
    const Vec2 ahead = *room - start.position;
    EXPECT_NEAR(ahead.norm(), 2.4, 0.6) << file;
    EXPECT_NEAR(std::atan2(ahead.y(), ahead.x()), start.heading, file.starts_with("worlds/") ? 1e-6 : 12 * pi / 180) << file;
  }
}

TEST(WanderAssignment, SolutionGetsFullMarksOnEveryCheck) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "solution.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kHall, 2}, {kTouch, 3}, {kExplore, 3}, {kUnseen, 2}}));
  EXPECT_EQ(g.score(), g.maxScore());
  for (const course::CheckGrade& c : g.checks) EXPECT_EQ(reasons(g, c.name), "") << c.name;
}

// The paper's runAround word for word, at the paper's 10 cm/s: it creeps out of the hall, then runs
// into what it meets at an angle (only its front sonar looks) and gets little further.
TEST(WanderAssignment, StarterCreepsOutAndTouches) {
  course::Grade g = gradeFile(kAssignment, assignmentFile(kAssignment, "starter.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kHall, 2}, {kTouch, 0}, {kExplore, 0}, {kUnseen, 0}}));
  EXPECT_THAT(reasons(g, kTouch), HasSubstr("in worlds/living_room.toml, seed 1: touched a round obstacle at 53.5 s"));
  EXPECT_THAT(reasons(g, kTouch), HasSubstr("in worlds/bedroom.toml, seed 1: touched a block at 77.0 s"));
  EXPECT_THAT(reasons(g, kExplore),
              HasSubstr("covered 12% of the floor it could reach 0.60 m or more from walls (5 of 40 cells of 0.50 m); 35% required"));
  EXPECT_THAT(judged(g, kUnseen), HasSubstr("touched a round obstacle"));
}

// It stops for anything within 50 cm of its five front sonars and always turns a quarter turn to
// the right: the door posts stop it in the doorway, and quarter turns to the right only ever send
// it back down the hall. It touches nothing, but that counts only for a robot that gets about.
TEST(WanderAssignment, QuarterTurnsToTheRightNeverLeaveTheHall) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "quarter_turns.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kHall, 0}, {kTouch, 0}, {kExplore, 0}, {kUnseen, 0}}));
  EXPECT_THAT(reasons(g, kHall), HasSubstr("in worlds/living_room.toml, seed 1: never came within 0.50 m of room (closest 1.61 m"));
  EXPECT_THAT(reasons(g, kTouch), HasSubstr("covered 3% of the floor it could reach (1 of 32 cells of 1.00 m); 25% required"));
  EXPECT_THAT(reasons(g, kExplore),
              HasSubstr("covered 0% of the floor it could reach 0.60 m or more from walls (0 of 40 cells of 0.50 m); 35% required"));
  EXPECT_EQ(failedIn(g, kUnseen), "generated furnished_room, hidden world 1\ngenerated furnished_room, hidden world 2\n");
  EXPECT_THAT(judged(g, kUnseen), HasSubstr("in hidden world 1: covered"));
}

// A good explorer that finds the walls with its bumpers: out of the hall and all over the rooms,
// touching every wall it turns away from.
TEST(WanderAssignment, StoppingOnTheBumperExploresButTouches) {
  course::Grade g = gradeFile(kAssignment, wrongSubmission(kAssignment, "stops_on_bumper.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kHall, 2}, {kTouch, 0}, {kExplore, 3}, {kUnseen, 0}}));
  EXPECT_THAT(reasons(g, kTouch),
              HasSubstr("in worlds/living_room.toml, seed 1: touched a round obstacle at 10.7 s at (4.0, 5.8) (14 collisions; 0 allowed)"));
  EXPECT_EQ(failedIn(g, kUnseen), "generated furnished_room, hidden world 1\ngenerated furnished_room, hidden world 2\n");
  EXPECT_THAT(judged(g, kUnseen), HasSubstr("in hidden world 1: touched a round obstacle at 2.7 s at (3.8, 1.9) (13 collisions; 0 allowed)"));
}

// Example 1 copied as it is: its goAhead also stops when anything is within 25 cm to a side, and
// its turnRight waits for 30 cm on both sides: it stops for the door posts, turns back down the
// hall, and spins for ever at the end of the hall, where no heading gives 30 cm on both sides.
TEST(WanderAssignment, Example1AsItIsNeverLeavesTheHall) {
  course::Grade g = gradeFile(kAssignment, example("01_run_around.cpp"));
  EXPECT_EQ(scores(g), (Scores{{kHall, 0}, {kTouch, 0}, {kExplore, 0}, {kUnseen, 0}}));
  EXPECT_THAT(reasons(g, kHall), HasSubstr("in worlds/bedroom.toml, seed 1: never came within 0.50 m of room (closest 1.62 m"));
  EXPECT_THAT(reasons(g, kTouch), HasSubstr("covered 3% of the floor it could reach (1 of 32 cells of 1.00 m); 25% required"));
  EXPECT_THAT(reasons(g, kExplore),
              HasSubstr("covered 0% of the floor it could reach 0.60 m or more from walls (0 of 40 cells of 0.50 m); 35% required"));
  EXPECT_THAT(judged(g, kUnseen),
              HasSubstr("in hidden world 2: covered 0% of the floor it could reach 0.60 m or more from walls (0 of 32 cells of 0.50 m)"));
}

}  // namespace
}  // namespace frob::testing
