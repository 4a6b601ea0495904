// Runs that explain themselves: each common mistake, fed to the diagnosis as a run would show it,
// gives the hint that names the fix; a good run gives none. And the paper's runAround written
// literally (one front sonar) is told why it keeps pushing against walls.
#include "frob/run/diagnose.hpp"

#include "frob/frob.hpp"
#include "frob/run/session.hpp"
#include "frob/worlds/registry.hpp"

#include <gtest/gtest.h>

namespace frob::course {
namespace {

using namespace frob::literals;

// A 6 x 4 m room's four walls.
std::vector<worlds::WallDef> room() {
  const Point2 a(0, 0), b(6, 0), c(6, 4), d(0, 4);
  std::vector<worlds::WallDef> w;
  for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) w.push_back(worlds::segmentWall(p, q));
  return w;
}

constexpr double kDt = 0.1;

TEST(Diagnosis, AGoodRunHasNoHint) {
  Diagnosis d(room(), {6, 4}, kDt);
  for (int k = 0; k <= 50; ++k) d.observe(0, k * kDt, {.position = {1 + 0.03 * k, 2}}, {0.3, 0}, 3.0, 6.5);
  EXPECT_TRUE(d.hints(0, "ada", {}, 5.0).empty());
}

TEST(Diagnosis, PushingAgainstAWallWithNoEchoSaysLookWithSeveralSonars) {
  Diagnosis d(room(), {6, 4}, kDt);
  // Stuck with its body against the right wall (centre 0.23 m from it) from 2.7 s on (the first step
  // it made less than a fifth of its 0.3 m/s there), still commanding 0.3 m/s: 7.3 s of pushing.
  for (int k = 0; k <= 100; ++k) {
    const double x = std::min(5.0 + 0.03 * k, 5.77);
    d.observe(0, k * kDt, {.position = {x, 2}}, {0.3, 0}, 6.5, 6.5);
  }
  const std::vector<std::string> h = d.hints(0, "ada", {}, 10.0);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0],
            "ada pushed against a wall for 7 s of the run while commanding forward speed (the first time from 2.7 s at (5.8, 2.0)); "
            "its front sonar read 6.5 m (no echo) there: a sonar misses a wall met at a grazing angle, so look ahead with several "
            "sonars (the nearest echo of sonars 14, 15, 0, 1 and 2) and end the task on the bumper too");
}

TEST(Diagnosis, PushingWhileTheSonarSawTheWallSaysEndTheTaskOnIt) {
  Diagnosis d(room(), {6, 4}, kDt);
  for (int k = 0; k <= 30; ++k) d.observe(0, k * kDt, {.position = {5.77, 2}}, {0.3, 0}, 0.15, 6.5);
  const std::vector<std::string> h = d.hints(0, "ada", {}, 3.0);
  ASSERT_EQ(h.size(), 2u);  // and it never moved
  EXPECT_NE(h[1].find("its front sonar read 0.15 m there: the task drove on regardless"), std::string::npos) << h[1];
}

TEST(Diagnosis, NeverMoved) {
  Diagnosis d(room(), {6, 4}, kDt);
  for (int k = 0; k <= 30; ++k) d.observe(0, k * kDt, {.position = {3, 2}}, {}, 6.5, 6.5);
  EXPECT_EQ(d.hints(0, "ada", {}, 3.0),
            std::vector<std::string>{"ada never moved: its controller commanded no motion at all (every wheel command was {0, 0})"});
}

// A robot that drove 4 cm and then stopped did move: no "never moved" (it was said below 5 cm).
TEST(Diagnosis, AFewCentimetresThenStoppingIsMoving) {
  Diagnosis d(room(), {6, 4}, kDt);
  for (int k = 0; k <= 30; ++k) d.observe(0, k * kDt, {.position = {3 + 0.01 * std::min(k, 4), 2}}, {0.1, 0}, 6.5, 6.5);
  EXPECT_TRUE(d.hints(0, "ada", {}, 3.0).empty());
}

TEST(Diagnosis, SpinningInPlace) {
  Diagnosis d(room(), {6, 4}, kDt);
  // 0.8 rad/s for 40 s: about 5 turns on the spot.
  for (int k = 0; k <= 400; ++k) d.observe(0, k * kDt, {.position = {3, 2}, .heading = std::remainder(0.08 * k, 2 * pi)}, {0, 0.8}, 6.5, 6.5);
  const std::vector<TaskRecord> running{{.id = 1, .parent = 0, .depth = 1, .name = "lookAround", .start = 0.0}};
  const std::vector<std::string> h = d.hints(0, "ada", running, 40.0);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(h[0],
            "ada spun in place 5 times from 0.1 s at (3.0, 2.0): a turn that waits for a condition that never comes (a sonar that "
            "cannot see the way out?)");
  EXPECT_EQ(h[1], "ada's task 'lookAround' ran from 0.0 s to the end of the run: the event that should end it never occurred");
}

// Tasks nested in each other that all ran to the end: one hint, for the innermost, not one per level.
TEST(Diagnosis, NestedTasksThatNeverEndGiveOneHint) {
  Diagnosis d(room(), {6, 4}, kDt);
  for (int k = 0; k <= 400; ++k) d.observe(0, k * kDt, {.position = {1 + 0.004 * k, 2}}, {0.4, 0}, 6.5, 6.5);
  const std::vector<TaskRecord> running{{.id = 1, .parent = 0, .depth = 1, .name = "follow", .start = 0.0},
                                        {.id = 2, .parent = 1, .depth = 2, .name = "alongWall", .start = 0.5},
                                        {.id = 3, .parent = 2, .depth = 3, .name = "keepDistance", .start = 1.0}};
  EXPECT_EQ(d.hints(0, "ada", running, 40.0),
            std::vector<std::string>{"ada's task 'keepDistance' (inside 'follow', 'alongWall') ran from 1.0 s to the end of the run: the event "
                                     "that should end it never occurred"});
  EXPECT_EQ(d.hints(0, "ada", running, 40.0, true), std::vector<std::string>{}) << "a follower meant to run for ever";
}

TEST(Diagnosis, TasksThatEndAsTheyBegin) {
  Diagnosis d(room(), {6, 4}, kDt);
  d.observe(0, 0, {.position = {1, 2}}, {0.3, 0}, 6.5, 6.5);
  d.observe(0, 1.0, {.position = {1.3, 2}}, {0.3, 0}, 6.5, 6.5);
  for (int k = 0; k < 30; ++k) {
    d.taskEnded(0, {.depth = 1, .name = k % 2 ? "turn" : "ahead", .start = 1.0, .end = 1.0, .how = TaskEnd::Returned});
  }
  const std::vector<std::string> h = d.hints(0, "ada", {}, 5.0);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].rfind("ada's tasks ended at the very instant they began 30 times ('ahead', 'turn')", 0), 0u) << h[0];
}

// A healthy program has tasks that end as they begin now and then (a turn already facing its goal,
// a task of plain code): 30 over a minute are no chain going round on the spot.
TEST(Diagnosis, TasksThatEndAsTheyBeginNowAndThenAreHealthy) {
  Diagnosis d(room(), {6, 4}, kDt);
  d.observe(0, 0, {.position = {1, 2}}, {0.3, 0}, 6.5, 6.5);
  d.observe(0, 60.0, {.position = {4, 2}}, {0.3, 0}, 6.5, 6.5);
  for (int k = 0; k < 30; ++k) {
    d.taskEnded(0, {.depth = 1, .name = "faceGoal", .start = 2.0 * k, .end = 2.0 * k, .how = TaskEnd::Returned});
  }
  EXPECT_TRUE(d.hints(0, "ada", {}, 60.0).empty());
}

// The paper's runAround as written there: one front sonar, 30 cm/s, 20 cm.
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(30_cm, 0), predicate(frontSonar(ts.robot()) < 20_cm)}; });
}
Task<Wheels> turnRight() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0, -0.5), predicate(frontSonar(ts.robot()) > 30_cm)}; });
}
Task<Wheels> runAround() {
  for (;;) {
    co_await goAhead();
    co_await turnRight();
  }
}

TEST(Diagnosis, ThePapersLiteralRunAroundIsToldWhyItPushesAgainstWalls) {
  Result<Summary> s = runSession({.world = *worlds::loadReferenceWorld("empty"),
                                  .worldName = "empty",
                                  .controllers = {{.entry = {.name = "runAround", .make = makeController(runAround)}, .source = "test"}},
                                  .seconds = 60});
  ASSERT_TRUE(s.ok()) << s.error();
  const std::vector<std::string>& hints = s.value().robots.at(0).hints;
  ASSERT_FALSE(hints.empty());
  EXPECT_NE(hints[0].find("nomad pushed against a wall for"), std::string::npos) << hints[0];
  EXPECT_NE(hints[0].find("its front sonar read 6.5 m (no echo) there: a sonar misses a wall met at a grazing angle"), std::string::npos) << hints[0];
}

}  // namespace
}  // namespace frob::course
