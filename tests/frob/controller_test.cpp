// FROB_CONTROLLER and makeController: every accepted shape of controller function gives the same
// wheels as writing the behavior by hand, and the declared options reach the entry.
#include "frob/frob.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

using namespace frob::literals;

Robot scripted() {
  return Robot(nomadSpec(), ScriptedSensors{.sonar = [](double t, int) { return 2.0 - t; }});
}

// Forward at the front sonar's range: a behavior.
Behavior<Wheels> follow(const Robot& r) { return wheels(frontSonar(r), 0.0); }
// The same as a task that ends when the range drops under 1 m (then the robot stops).
Task<Wheels> followTask() {
  return mkTask([](const TaskState& ts) { return std::pair{follow(ts.robot()), predicate(frontSonar(ts.robot()) < 1.0)}; });
}
Task<Wheels> followTaskOf(const Robot&) { return followTask(); }

std::vector<double> forwardAt(const Controller& c, int steps) {
  Robot r = scripted();
  Behavior<Wheels> b = c(r);
  Clock clock(0.25);
  std::vector<double> out;
  for (int i = 0; i < steps; ++i) out.push_back(b.at(i == 0 ? clock.now() : clock.advance()).forward);
  return out;
}

TEST(Controller, BehaviorOfRobot) { EXPECT_EQ(forwardAt(makeController(follow), 3), (std::vector<double>{2.0, 1.75, 1.5})); }

TEST(Controller, PointwiseExpressionOfRobot) {
  auto expr = [](const Robot& r) { return lift([](double d) { return Wheels{d, 0.0}; }, frontSonar(r)); };
  EXPECT_EQ(forwardAt(makeController(expr), 2), (std::vector<double>{2.0, 1.75}));
}

TEST(Controller, TaskRunsUntilItEndsThenStops) {
  // The range is under 1 m from t = 1.25: the task ends and the default final behavior stops.
  const std::vector<double> expected{2.0, 1.75, 1.5, 1.25, 1.0, 0.0, 0.0};
  EXPECT_EQ(forwardAt(makeController(followTask), 7), expected);
  EXPECT_EQ(forwardAt(makeController(followTaskOf), 7), expected);
}

TEST(RunningController, FailsOnNonFiniteWheelsAndStopsFromThenOn) {
  Robot r = scripted();
  RunningController c([](const Robot& robot) { return wheels(1.0 / (frontSonar(robot) - 1.5), 0.0); }, r);
  Clock clock(0.25);
  EXPECT_EQ(c.step(clock.now()).forward, 2.0);  // 1 / (2 - 1.5)
  EXPECT_FALSE(c.failed());
  (void)c.step(clock.advance());                    // 1 / (1.75 - 1.5) = 4
  EXPECT_EQ(c.step(clock.advance()).forward, 0.0);  // 1 / 0: infinite
  EXPECT_TRUE(c.failed());
  EXPECT_EQ(c.failure(), "the controller commanded non-finite wheels {forward inf m/s, turn 0.000 rad/s} at t = 0.500 s");
  EXPECT_EQ(c.step(clock.advance()).forward, 0.0);
}

// Finished means "a stop for ever" (the host is then asked no more): a controller function's task
// that returned, never a behavior that runs a task of its own and goes on after it.
TEST(RunningController, IsFinishedOnceItsTaskHasReturnedAndOnlyThen) {
  const auto finishedAt = [](const Controller& make) {
    Robot r = scripted();
    RunningController c(make, r);
    Clock clock(0.25);
    std::vector<bool> finished;
    for (int i = 0; i < 7; ++i) {
      (void)c.step(i == 0 ? clock.now() : clock.advance());
      finished.push_back(c.finished());
    }
    return finished;
  };
  // The range is under 1 m from t = 1.25 (the sixth step): the task ends there.
  EXPECT_EQ(finishedAt(makeController(followTask)), (std::vector<bool>{false, false, false, false, false, true, true}));
  EXPECT_EQ(finishedAt(makeController(follow)), std::vector<bool>(7, false));
  const auto goesOn = [](const Robot& r) { return runTask(TaskState(r), followTask(), Behavior<Wheels>(Wheels{0.5, 0.0})); };
  EXPECT_EQ(finishedAt(goesOn), std::vector<bool>(7, false));
  // A behavior that is runTask(robot, task) is a task's controller; one that holds it inside another is not.
  const auto runsIt = [](const Robot& r) { return runTask(r, followTask()); };
  EXPECT_EQ(finishedAt(runsIt), (std::vector<bool>{false, false, false, false, false, true, true}));
  const auto holdsIt = [](const Robot& r) { return toBehavior(lift([](const Wheels& w, double) { return w; }, runTask(r, followTask()), time())); };
  EXPECT_EQ(finishedAt(holdsIt), std::vector<bool>(7, false));
}

TEST(RunningController, ABuildThatThrowsOrAnAllocationThatFailsIsAReason) {
  Robot r = scripted();
  RunningController bad([](const Robot&) -> Behavior<Wheels> { throw std::runtime_error("no sonar"); }, r);
  EXPECT_TRUE(bad.failed());
  EXPECT_EQ(bad.failure(), "building its controller failed: no sonar");
  RunningController hungry([](const Robot&) { return toBehavior(lift([](double) -> Wheels { throw std::bad_alloc(); }, time())); }, r);
  (void)hungry.step(Clock(0.1).now());
  EXPECT_EQ(hungry.failure(), "ran out of memory (std::bad_alloc): it allocated more than a controller may");
}

}  // namespace

// The declaration a controller file ends with, here under a name of its own.
#undef FROB_CONTROLLER_SYMBOL
#define FROB_CONTROLLER_SYMBOL controllerTestEntry
FROB_CONTROLLER(followTask, .world = "corridor", .seconds = 12.5, .summary = "follows")

TEST(Controller, MacroDeclaresTheEntryWithItsOptions) {
  const ControllerEntry* e = controllerTestEntry();
  EXPECT_EQ(e->name, "followTask");
  EXPECT_EQ(e->options.world, "corridor");
  EXPECT_EQ(e->options.seconds, 12.5);
  EXPECT_EQ(e->options.summary, "follows");
  EXPECT_EQ(forwardAt(e->make, 2), (std::vector<double>{2.0, 1.75}));
  EXPECT_EQ(controllerTestEntry(), e);  // one entry, built once
}

}  // namespace frob
