#include "frob/frob.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace frob {
namespace {

using namespace literals;

Robot idleRobot() { return Robot(nomadSpec(), ScriptedSensors{}); }

Task<Wheels> drive(double forward, double seconds) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, 0), after(seconds)}; });
}
Task<Wheels> forever(double forward) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, 0), never()}; });
}

std::vector<double> forwardOf(const Behavior<Wheels>& b, int steps) {
  std::vector<double> out;
  for (const Wheels& w : sample(b, 0.1, steps)) out.push_back(w.forward);
  return out;
}

TEST(Transformers, AddErrorCoversEverySubtaskAndEndsWithTheWrappedTask) {
  // The error event occurs at t = 0.25 local to the scope, while the scope's second subtask runs.
  auto seq = []() -> Task<Wheels> {
    auto inner = []() -> Task<Wheels> {
      co_await drive(1, 0.1);
      co_await forever(2);
    };
    std::string caught;
    try {
      co_await addError(after(0.25).map([] { return RoboErr("scoped"); }), inner());
    } catch (const RoboErr& e) {
      caught = e.what();
    }
    EXPECT_EQ(caught, "scoped");
    // The handler's tasks start at the error's instant, 0.25 s, though it is sampled at 0.3 s: this
    // one ends at 0.35 s (sampled at 0.4 s). A scope that ended no longer raises: its event, due
    // 0.2 s after it began (sampled at 0.5 s), is ignored here.
    co_await addError(after(0.2).map([] { return RoboErr("late"); }), drive(3, 0.1));
    co_await drive(4, 1.0);
  };
  EXPECT_EQ(forwardOf(runTask(idleRobot(), seq()), 7), (std::vector<double>{1, 2, 2, 3, 4, 4, 4}));
}

// One occurrence is delivered once (event.hpp): an addError event that occurs once, at t = 0.3,
// fails the subtask running then; the inner handler catches it, and the task it starts in that
// instant runs on: the outer handler never hears of it.
TEST(Transformers, AScopedErrorsOneOccurrenceIsCaughtOnceByTheInnermostHandler) {
  int inner = 0, outer = 0;
  auto t = taskCatch(addError(after(0.3).map([] { return RoboErr("bump"); }), taskCatch(forever(1),
                                                                                        [&inner](const RoboErr&) {
                                                                                          ++inner;
                                                                                          return drive(2, 0.25);
                                                                                        })),
                     [&outer](const RoboErr&) {
                       ++outer;
                       return forever(9);
                     });
  const std::vector<double> f = forwardOf(runTask(idleRobot(), Task<Wheels>(std::move(t))), 8);
  EXPECT_EQ(f, (std::vector<double>{1, 1, 1, 2, 2, 2, 0, 0}));  // 2 from 0.3 to 0.55, then the run's end
  EXPECT_EQ(inner, 1);
  EXPECT_EQ(outer, 0);
}

// The paper's BUG pattern under addError: one occurrence restarts the attempt once, not a thousand
// times in one instant; a second occurrence restarts it again.
TEST(Transformers, ARestartingHandlerRestartsOncePerOccurrenceOfAScopedError) {
  int restarts = 0;
  auto attempts = [&restarts]() -> Task<Wheels> {
    for (;;) {
      try {
        co_await forever(1 + restarts);
      } catch (const RoboErr&) {
        ++restarts;
      }
    }
  };
  auto t = addError(every(0.3).map([] { return RoboErr("bump"); }), attempts());
  const std::vector<double> f = forwardOf(runTask(idleRobot(), std::move(t)), 8);
  EXPECT_EQ(f, (std::vector<double>{1, 1, 1, 2, 2, 2, 3, 3}));
  EXPECT_EQ(restarts, 2);
}

// One occurrence is delivered once whichever event carries it: each attempt builds its own error
// event from the keyboard, as mkTaskE builds a task's events from its state. The key pressed at
// 0.3 s fails the attempt running then; the attempt restarted in that instant does not see that
// press again (it used to fail again and again, until "ended at its start more than 1000 times").
TEST(Transformers, AnOccurrenceIsDeliveredOnceWhicheverEventCarriesIt) {
  Robot r(nomadSpec(), ScriptedSensors{.keys = [](double t) { return std::abs(t - 0.3) < 1e-9 ? std::vector<char>{'x'} : std::vector<char>{}; }});
  int restarts = 0;
  auto attempts = [&restarts]() -> Task<Wheels> {
    for (;;) {
      try {
        co_await mkTaskE([&restarts](const TaskState& ts) {
          return std::tuple{wheels(1 + restarts, 0), never(), keyboard(ts.robot()).as(RoboErr("key"))};
        });
      } catch (const RoboErr&) {
        ++restarts;
      }
    }
  };
  EXPECT_EQ(forwardOf(runTask(r, attempts()), 6), (std::vector<double>{1, 1, 1, 2, 2, 2}));
  EXPECT_EQ(restarts, 1);
}

// Only an occurrence that ended or failed a task is used up: a time limit that expires in the
// instant its body's first subtask ends (the exit wins the tie) still ends the next subtask.
TEST(Transformers, AScopesOccurrenceThatLostATieStillEndsTheNextTask) {
  bool inTime = true;
  auto t = [&inTime]() -> Task<Wheels> {
    auto body = []() -> Task<Wheels> {
      co_await drive(1, 0.3);
      co_await forever(2);
    };
    inTime = co_await timeLimit(body(), 0.3);
    co_await drive(3, 0.2);
  };
  EXPECT_EQ(forwardOf(runTask(idleRobot(), t()), 6), (std::vector<double>{1, 1, 1, 3, 3, 0}));
  EXPECT_FALSE(inTime);
}

// A sequence's next task, started in the instant the previous one ended on a stored event, does
// not end at once on that same occurrence: it waits for the next one.
TEST(Transformers, TheNextTaskOfASequenceDoesNotSeeTheOccurrenceThatEndedTheLastOne) {
  const Event<Unit> tick = every(0.3).as(Unit{});
  auto seq = [tick]() -> Task<Wheels> {
    co_await mkTask([tick](const TaskState&) { return std::pair{wheels(1, 0), tick}; });
    co_await mkTask([tick](const TaskState&) { return std::pair{wheels(2, 0), tick}; });
  };
  EXPECT_EQ(forwardOf(runTask(idleRobot(), seq()), 8), (std::vector<double>{1, 1, 1, 2, 2, 2, 0, 0}));
}

Task<Wheels, int> driveThen(double forward, double seconds, int result) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, 0), after(seconds).map([result] { return result; })}; });
}

// A task with a result gives std::optional of it; one without gives whether it ended in time.
static_assert(std::is_same_v<decltype(timeLimit(driveThen(3, 0.1, 5), 1.0)), Task<Wheels, std::optional<int>>>);
static_assert(std::is_same_v<decltype(timeLimit(drive(2, 0.1), 1.0)), Task<Wheels, bool>>);

TEST(Transformers, TimeLimitAbortsOrPassesTheResultThrough) {
  bool late = true;
  bool early = false;
  std::optional<int> value;
  std::optional<int> cut = 0;
  auto seq = [&]() -> Task<Wheels> {
    late = co_await timeLimit(forever(1), 0.3);
    early = co_await timeLimit(drive(2, 0.1), 1.0);
    value = co_await timeLimit(driveThen(3, 0.1, 5), 1.0);
    cut = co_await timeLimit(driveThen(4, 1.0, 6), 0.1);
  };
  std::vector<double> f = forwardOf(runTask(idleRobot(), seq()), 8);
  EXPECT_FALSE(late);  // cut short at 0.3 s
  EXPECT_TRUE(early);  // ended at 0.1 s, within its 1 s
  EXPECT_EQ(value, 5);
  EXPECT_EQ(cut, std::nullopt);
  EXPECT_EQ(f, (std::vector<double>{1, 1, 1, 2, 3, 4, 0, 0}));
}

// A task with a result gives it paired with the behavior's value; one without, the value alone.
static_assert(std::is_same_v<decltype(withB([](const TaskState&) { return time(); }, driveThen(1, 0.2, 8))), Task<Wheels, std::pair<int, double>>>);
static_assert(std::is_same_v<decltype(withB([](const TaskState&) { return time(); }, drive(1, 0.5))), Task<Wheels, double>>);

TEST(Transformers, WithBPairsTheResultWithTheBehaviorAtTheEnd) {
  double got = 0;
  std::pair<int, double> both;
  auto seq = [&]() -> Task<Wheels> {
    got = co_await withB([](const TaskState&) { return integral(constant(2.0)); }, drive(1, 0.5));
    both = co_await withB([](const TaskState&) { return integral(constant(3.0)); }, driveThen(1, 0.2, 8));
  };
  (void)forwardOf(runTask(idleRobot(), seq()), 9);
  EXPECT_NEAR(got, 1.0, 1e-12);  // 2 m/s for the task's 0.5 s
  EXPECT_EQ(both.first, 8);
  EXPECT_NEAR(both.second, 0.6, 1e-12);  // 3 m/s for 0.2 s
}

// Issue 15: withB's function gets the state of withB's start by value, as mkTask's does. A
// reference it keeps into that state (here the start place) must not follow the subtasks' states.
TEST(Transformers, WithBGivesItsFunctionTheStateOfItsStartByValue) {
  Robot r(nomadSpec(), ScriptedSensors{.odometry = [](double t) { return Pose2{Point2{t, 0}, 0}; }});
  double travelled = 0;
  auto twoLegs = []() -> Task<Wheels> {
    co_await drive(1, 0.5);
    co_await drive(1, 0.3);
  };
  auto seq = [&]() -> Task<Wheels> {
    co_await drive(1, 0.2);
    travelled = co_await withB(
        [](const TaskState& ts) {
          const Point2& start = ts.initialPlace();  // kept by reference, as students write
          return lift([&start](const Point2& p) { return distance(p, start); }, place(ts.robot()));
        },
        twoLegs());
  };
  (void)forwardOf(runTask(r, seq()), 12);
  EXPECT_NEAR(travelled, 0.8, 1e-12);  // from x = 0.2 to x = 1.0, not from the second leg's start (0.3)
}

TEST(Transformers, WithExitAbortsAndReturnsTheEventsValue) {
  int value = 0;
  std::string error;
  auto seq = [&]() -> Task<Wheels> {
    value = co_await withExit(after(0.2).map([] { return 42; }), forever(1));
    try {
      co_await withExit(after(5.0).map([] { return 0; }), drive(2, 0.1));
    } catch (const RoboErr& e) {
      error = e.what();
    }
  };
  (void)forwardOf(runTask(idleRobot(), seq()), 6);
  EXPECT_EQ(value, 42);
  EXPECT_NE(error.find("ended before its withExit event"), std::string::npos) << error;
}

// Issue 15: the paper's withExit is an untilB around the body, so when the body ends at the very
// instant the event occurs, the event wins: withExit returns its value, not an error.
TEST(Transformers, WithExitWinsATieWithItsBodysEnd) {
  int value = 0;
  auto seq = [&]() -> Task<Wheels> {
    co_await drive(1, 0.2);
    value = co_await withExit(after(1.0).map([] { return 42; }), drive(2, 1.0));
    co_await forever(3);
  };
  std::vector<double> f = forwardOf(runTask(idleRobot(), seq()), 14);
  EXPECT_EQ(value, 42);
  EXPECT_EQ(f[11], 2);  // t = 1.1: the body still drives
  EXPECT_EQ(f[12], 3);  // t = 1.2: both ended together, and the next task drives in that step
}

TEST(Transformers, WithMyResultSeesItsOwnOutputOneStepLate) {
  // Output: 1 + my previous output, so 1, 2, 3, ... (and 1 at the start, from the zero before).
  auto counting = withMyResult([](Behavior<Wheels> mine) {
    return mkTask([mine](const TaskState&) { return std::pair{lift([](const Wheels& w) { return Wheels{w.forward + 1, 0}; }, mine), never()}; });
  });
  EXPECT_EQ(forwardOf(runTask(idleRobot(), std::move(counting)), 4), (std::vector<double>{1, 2, 3, 4}));
}

// Issue 15: a generic lambda is accepted; its argument is the robot's output, a Behavior<Wheels>.
TEST(Transformers, WithMyResultTakesAGenericLambda) {
  auto counting = withMyResult([](auto mine) {
    return mkTask([mine](const TaskState&) { return std::pair{wheels(mine.map(&Wheels::forward) + 1.0, 0), never()}; });
  });
  EXPECT_EQ(forwardOf(runTask(idleRobot(), std::move(counting)), 3), (std::vector<double>{1, 2, 3}));
}

TEST(Transformers, WithFilterAppliesToEverySubtaskAndStopsAfter) {
  auto seq = []() -> Task<Wheels> {
    auto inner = []() -> Task<Wheels> {
      co_await drive(1, 0.1);
      co_await drive(2, 0.1);
    };
    co_await withFilter([](const Wheels& w) { return Wheels{w.forward * 10, w.turn}; }, inner());
    co_await withFilter(
        [](Behavior<Wheels> b) {
          return lift([](Wheels w, double t) { return Wheels{w.forward + t, 0}; }, b, time());
        },
        drive(3, 0.2));
    co_await drive(4, 1);
  };
  std::vector<double> f = forwardOf(runTask(idleRobot(), seq()), 6);
  EXPECT_EQ(f[0], 10);
  EXPECT_EQ(f[1], 20);
  EXPECT_NEAR(f[2], 3.0, 1e-12);
  EXPECT_NEAR(f[3], 3.1, 1e-12);
  EXPECT_EQ(f[4], 4);
}

Task<Wheels, bool> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    return std::pair{wheels(0.5, 0), predicate(distance(place(ts.robot()), goal) < 0.1).map([] { return true; })};
  });
}
Task<Wheels, bool> driveToWithPicture(Point2 goal) { return withPicture(paintAt(goal, withColor(red, circle(10_cm))), driveTo(goal)); }

TEST(Transformers, WithPictureIsPublishedWhileTheTaskRunsAtTheRightPlace) {
  Robot r(nomadSpec(), ScriptedSensors{.odometry = [](double t) { return Pose2{Point2{0.5 * t, 0}, 0}; }});
  auto seq = []() -> Task<Wheels> {
    co_await withPicture(withColor(blue, text("outer")), driveToWithPicture(Point2{1, 0}));
    co_await forever(0);
  };
  Behavior<Wheels> c = runTask(r, seq());
  Clock clock(0.1);
  (void)c.at(clock.now());
  Picture during = r.debugChannel()->picture(clock.now());
  ASSERT_EQ(during.shapes().size(), 2u);  // the outer text and the goal circle
  EXPECT_EQ(during.shapes()[1].kind, Shape::Kind::Circle);
  EXPECT_EQ(during.shapes()[1].points[0], Point2(1, 0));
  EXPECT_EQ(during.shapes()[1].color, red);
  EXPECT_DOUBLE_EQ(during.shapes()[1].radius, 0.1);
  for (int i = 0; i < 30; ++i) (void)c.at(clock.advance());
  EXPECT_TRUE(r.debugChannel()->picture(clock.now()).empty());  // the goal was reached at t = 1.8
}

// The task stack names a plot as a plot, with what it plots.
TEST(Transformers, WithPlotIsNamedForThePlot) {
  EXPECT_EQ(withPlot("left", Behavior<double>(0.5), driveTo(Point2{1, 0}).named("approach")).name(), "withPlot(left, approach)");
  EXPECT_EQ(driveToWithPicture(Point2{1, 0}).named("approach").name(), "approach");
}

TEST(Transformers, AbortedTasksFreeTheirFramesAndBehaviors) {
  long frames0 = liveTaskFrames();
  long nodes0 = 0;
  Robot r = idleRobot();
  auto nested = []() -> Task<Wheels> {
    auto deep = []() -> Task<Wheels> { co_await withPicture(circle(1), forever(1)); };
    co_await withFilter([](const Wheels& w) { return w; }, deep());
  };
  auto seq = [&nested]() -> Task<Wheels> {
    (void)co_await timeLimit(nested(), 0.3);
    (void)co_await withExit(after(0.2).map([] { return 1; }), nested());
    co_await forever(0);
  };
  Behavior<Wheels> c = runTask(r, seq());
  Clock clock(0.1);
  (void)c.at(clock.now());
  long during = liveTaskFrames() - frames0;
  for (int i = 0; i < 4; ++i) (void)c.at(clock.advance());
  nodes0 = liveNodeCount();
  for (int i = 0; i < 6; ++i) (void)c.at(clock.advance());
  EXPECT_GE(during, 6);                      // seq, timeLimit, nested, filter, deep, picture, atomic
  EXPECT_LE(liveTaskFrames() - frames0, 2);  // seq and its final forever
  EXPECT_LT(liveNodeCount(), nodes0);        // the aborted graphs are gone
  EXPECT_TRUE(r.debugChannel()->picture(clock.now()).empty());
  std::vector<TaskRecord> ended = r.debugChannel()->timeline().drainEnded();
  int aborted = 0;
  for (const TaskRecord& rec : ended) aborted += rec.how == TaskEnd::Aborted;
  EXPECT_GE(aborted, 8);
}

}  // namespace
}  // namespace frob

namespace frob {
namespace {

Task<Wheels> failing(double seconds) {
  return mkTaskE([=](const TaskState&) { return std::tuple{wheels(-1, 0), never(), after(seconds).as(RoboErr("lost"))}; });
}

// The paper's bug as course/examples/06_bug.cpp writes it: an attempt becomes goAround, which
// becomes bug again, inside the attempt's taskCatch; every third attempt fails and the handler
// restarts bug. Each round's taskCatch has the same handler, so it folds into the one it runs in.
Task<Wheels> bugShape(int* rounds);
Task<Wheels> goAroundShape(int* rounds) {
  co_await drive(1, 0.1);
  co_await become(bugShape(rounds));
}
Task<Wheels> attemptShape(int* rounds) {
  if (++*rounds % 3 == 0) co_await failing(0.1);
  co_await drive(2, 0.1);
  co_await become(goAroundShape(rounds));
}
Task<Wheels> bugShape(int* rounds) {
  return taskCatch(attemptShape(rounds), [rounds](const RoboErr&) { return bugShape(rounds); });
}

// Each round nested one more taskCatch: 582 live frames after 60 s, and the run stopped at 1,000.
// Now 10,000 rounds (about 1,700 s) keep the frames and nodes of one round: the taskCatch, the
// attempt or goAround, the atomic task.
TEST(Transformers, BugRestartingItselfInsideTaskCatchRunsInBoundedDepthAndMemory) {
  const long frames0 = liveTaskFrames(), nodes0 = liveNodeCount();
  int rounds = 0;
  long maxFrames = 0, maxNodes = 0;
  {
    Robot r = idleRobot();
    Behavior<Wheels> c = runTask(r, bugShape(&rounds));
    Clock clock(0.1);
    for (std::int64_t i = 0; rounds <= 10'000; ++i) {
      ASSERT_EQ(c.at(i == 0 ? clock.now() : clock.advance()).forward == 0, false) << "stopped at round " << rounds;
      maxFrames = std::max(maxFrames, liveTaskFrames() - frames0);
      maxNodes = std::max(maxNodes, liveNodeCount() - nodes0);
      if (i % 1000 == 0) r.debugChannel()->timeline().drainEnded();
    }
  }
  EXPECT_LE(maxFrames, 4);
  EXPECT_LE(maxNodes, 40);
  EXPECT_EQ(liveTaskFrames(), frames0);
}

// Folding keeps the meaning of nesting: a taskCatch whose task became another with the same
// handler handles two errors, the second raised by the handler's own task, as two nested ones do.
Task<Wheels> guarded(Task<Wheels> t, int* calls) {
  return taskCatch(std::move(t), [calls](const RoboErr&) {
    ++*calls;
    return failing(0.1);
  });
}
Task<Wheels> thenGuarded(int* calls) {
  co_await drive(1, 0.1);
  co_await become(guarded(failing(0.1), calls));
}

TEST(Transformers, AFoldedTaskCatchHandlesAsManyErrorsAsTheNestedOnes) {
  int calls = 0;
  std::string failure;
  try {
    (void)forwardOf(runTask(idleRobot(), guarded(thenGuarded(&calls), &calls)), 6);
  } catch (const FrobError& e) {
    failure = e.what();
  }
  EXPECT_EQ(calls, 2);  // at 0.2 s and at 0.3 s; the third error, at 0.4 s, ends the run
  EXPECT_NE(failure.find("failed at t = 0.400 s: error: lost"), std::string::npos) << failure;
}

// Handlers that differ (another captured value) do not fold: the inner one handles first.
TEST(Transformers, TaskCatchesWithDifferentHandlersStayNested) {
  std::vector<int> handled;
  auto tagged = [&handled](Task<Wheels> t, int tag) {
    return taskCatch(std::move(t), [&handled, tag](const RoboErr&) {
      handled.push_back(tag);
      return failing(0.1);
    });
  };
  auto body = [&tagged]() -> Task<Wheels> {
    co_await drive(1, 0.1);
    co_await become(tagged(failing(0.1), 2));
  };
  EXPECT_THROW((void)forwardOf(runTask(idleRobot(), tagged(body(), 1)), 6), FrobError);
  EXPECT_EQ(handled, (std::vector<int>{2, 1}));
}

// A handler that differs each round (it captures the round's number) cannot fold: the rounds nest
// until the run stops at 1,000, with a message that names the taskCatch and what to capture instead
// (it used to advise `co_await become(taskCatch(countingAttempt)());`, which is not C++).
Task<Wheels> countingBug(int round);
Task<Wheels> countingAttempt(int round) {
  co_await drive(1, 0.1);
  co_await become(countingBug(round + 1));
}
Task<Wheels> countingBug(int round) {
  return taskCatch(countingAttempt(round), [round](const RoboErr&) { return countingBug(round + 1); });
}

TEST(Transformers, ATaskCatchThatCannotFoldStopsWithAHintThatNamesIt) {
  std::string failure;
  try {
    (void)sample(runTask(idleRobot(), countingBug(0)), 0.1, 2000);
  } catch (const FrobError& e) {
    failure = e.what();
  }
  EXPECT_NE(failure.find("the taskCatch(countingAttempt) made at task_transformers_test.cpp:"), std::string::npos) << failure;
  EXPECT_NE(failure.find("[g](const RoboErr&) { return bug(g); }"), std::string::npos) << failure;
  EXPECT_EQ(failure.find("become(taskCatch("), std::string::npos) << failure;
}

}  // namespace
}  // namespace frob
