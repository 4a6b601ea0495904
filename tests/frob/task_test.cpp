#include "frob/frob.hpp"
#include "kinematic_robot.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <ostream>
#include <tuple>
#include <variant>

// Results a student's task may return, named as a student names them (global, not in frob).
namespace {
enum class Side { left, right };
std::ostream& operator<<(std::ostream& os, Side s) { return os << (s == Side::left ? "left" : "right"); }
enum Colour { redColour, greenColour };  // no operator<<: an enum would print as a number
struct Gap {                             // no operator<<
  double width = 0;
};
struct Seen {
  int count = 0;
};
std::ostream& operator<<(std::ostream& os, const Seen& s) { return os << s.count << " seen"; }
}  // namespace

namespace frob {
namespace {

using namespace literals;
using testing::KinematicRobot;

Robot idleRobot() { return Robot(nomadSpec(), ScriptedSensors{}); }

// Runs `b` for `steps` of `dt`, collecting its samples.
std::vector<Wheels> samples(const Behavior<Wheels>& b, double dt, int steps) { return sample(b, dt, steps); }

Task<Wheels> forwardFor(double speed, double seconds) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(speed, 0), after(seconds)}; });
}

Task<Wheels, int> countTo(int n) {
  return mkTask([n](const TaskState&) {
    return std::pair{wheels(0, n), every(0.1).filter([n](std::int64_t k) { return k == n; }).map([](std::int64_t k) { return static_cast<int>(k); })};
  });
}

TEST(Task, MkTaskRunsItsBehaviorUntilItsEventAndSwitchesInThatStep) {
  auto seq = []() -> Task<Wheels> {
    co_await forwardFor(1.0, 0.3);
    co_await forwardFor(2.0, 0.2);
  };
  std::vector<Wheels> s = samples(runTask(idleRobot(), seq()), 0.1, 7);
  std::vector<double> forward;
  for (const Wheels& w : s) forward.push_back(w.forward);
  // The first task's event occurs at t = 0.3: the second drives from that very step.
  EXPECT_EQ(forward, (std::vector<double>{1, 1, 1, 2, 2, 0, 0}));  // then the final behavior: stop
}

TEST(Task, CoAwaitYieldsTheResultOfTheEvent) {
  int got = 0;
  auto seq = [](int* out) -> Task<Wheels> { *out = co_await countTo(3); };
  (void)samples(runTask(idleRobot(), seq(&got)), 0.1, 5);
  EXPECT_EQ(got, 3);
}

TEST(Task, ATasksBehaviorsStartWithTheTask) {
  // time() and integral built in the second task's mkTask count from that task's start.
  auto seq = []() -> Task<Wheels> {
    co_await forwardFor(0.0, 0.5);
    co_await mkTask([](const TaskState&) { return std::pair{wheels(integral(constant(1.0)), time()), never()}; });
  };
  std::vector<Wheels> s = samples(runTask(idleRobot(), seq()), 0.1, 8);
  EXPECT_EQ(s[5].forward, 0.0);
  EXPECT_EQ(s[5].turn, 0.0);
  EXPECT_NEAR(s[7].forward, 0.2, 1e-12);
  EXPECT_NEAR(s[7].turn, 0.2, 1e-12);
}

TEST(Task, ChainsOfZeroDurationTasksRunInOneStep) {
  auto instant = [](double v) { return mkTask([v](const TaskState&) { return std::pair{wheels(v, 0), predicate(constant(true))}; }); };
  auto seq = [&instant]() -> Task<Wheels> {
    for (int i = 0; i < 50; ++i) co_await instant(i);
    co_await forwardFor(99, 1.0);
  };
  EXPECT_EQ(samples(runTask(idleRobot(), seq()), 0.1, 1)[0].forward, 99.0);
}

Task<Wheels> alreadyDone() {
  return mkTask([](const TaskState&) { return std::pair{wheels(1, 0), predicate(constant(true))}; });
}

TEST(Task, AnEndlessChainAtOneInstantIsAnErrorNamingTheTask) {
  auto loop = []() -> Task<Wheels> {
    for (;;) co_await alreadyDone();
  };
  Behavior<Wheels> b = runTask(idleRobot(), loop());
  try {
    (void)samples(b, 0.1, 1);
    FAIL() << "no error";
  } catch (const FrobError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("'alreadyDone'"), std::string::npos) << m;
    EXPECT_NE(m.find("t = 0.000 s"), std::string::npos) << m;
  }
}

TEST(Task, TaskStateCapturesThePoseAtEachTransition) {
  // "Turn right 90 degrees": a task that can only be written with initialOrientation.
  auto turnRight = []() {
    return mkTask([](const TaskState& ts) {
      double goal = wrapAngle(ts.initialOrientation() - 90_deg);
      Behavior<double> error = wrapAngle(goal - orientation(ts.robot()));
      return std::pair{wheels(0, clamp(error * 2.0, -1.0, 1.0)), predicate(abs(error) < 1_deg)};
    });
  };
  auto seq = [&turnRight]() -> Task<Wheels> {
    TaskState first = co_await getTaskState();
    EXPECT_EQ(first.initialOrientation(), 0.3);
    co_await turnRight();
    TaskState after = co_await getTaskState();
    EXPECT_NEAR(after.initialOrientation(), wrapAngle(0.3 - 90_deg), 1_deg);
    EXPECT_GT(after.startTime(), 0.5);
    co_await setTaskState(TaskState(after).setInitialOrientation(0.0));
    EXPECT_EQ((co_await getTaskState()).initialOrientation(), 0.0);
  };
  KinematicRobot k(3.0, Pose2{Point2::Zero(), 0.3});
  k.run(runTask(k.robot(), seq()), 0.01, 5.0);
  EXPECT_NEAR(k.pose().heading, wrapAngle(0.3 - 90_deg), 1_deg);
}

Task<Wheels> failAfter(double seconds, std::string why) {
  return mkTaskE([=](const TaskState&) { return std::tuple{wheels(0.1, 0), never(), after(seconds).map([why] { return RoboErr(why); })}; });
}
Task<Wheels> level3() { co_await failAfter(0.2, "deep"); }
Task<Wheels> level2() {
  co_await level3();
  ADD_FAILURE() << "the error did not unwind level2";
}
Task<Wheels> level1() { co_await level2(); }

TEST(Task, AnErrorDeepInsidePropagatesToTheNearestCatch) {
  std::string caught;
  auto withTry = [](std::string* out) -> Task<Wheels> {
    try {
      co_await level1();
    } catch (const RoboErr& e) {
      *out = e.what();
    }
    co_await forwardFor(5, 1);
  };
  std::vector<Wheels> s = samples(runTask(idleRobot(), withTry(&caught)), 0.1, 4);
  EXPECT_EQ(caught, "deep");
  EXPECT_EQ(s[2].forward, 5.0);  // the error at t = 0.2 hands over in the same step

  std::string handled;
  auto recover = [&handled](const RoboErr& e) {
    handled = e.what();
    return forwardFor(7, 1);
  };
  std::vector<Wheels> t = samples(runTask(idleRobot(), taskCatch(level1(), recover)), 0.1, 4);
  EXPECT_EQ(handled, "deep");
  EXPECT_EQ(t[3].forward, 7.0);
}

TEST(Task, TaskErrorRaisesAsAnAwaitAndAsATask) {
  auto viaAwait = []() -> Task<Wheels> { co_await taskError(RoboErr("by await")); };
  auto viaReturn = []() -> Task<Wheels> { return taskError(RoboErr("by return")); };
  std::string a, b;
  (void)samples(runTask(idleRobot(), taskCatch(viaAwait(),
                                               [&a](const RoboErr& e) {
                                                 a = e.what();
                                                 return forwardFor(0, 1);
                                               })),
                0.1, 1);
  (void)samples(runTask(idleRobot(), taskCatch(viaReturn(),
                                               [&b](const RoboErr& e) {
                                                 b = e.what();
                                                 return forwardFor(0, 1);
                                               })),
                0.1, 1);
  EXPECT_EQ(a, "by await");
  EXPECT_EQ(b, "by return");
}

Task<Wheels> throwsLogicError() {
  co_await forwardFor(1, 0.3);
  throw std::logic_error("student bug");
}

TEST(Task, AnUncaughtExceptionNamesTheTaskAndTheTime) {
  Behavior<Wheels> b = runTask(idleRobot(), throwsLogicError());
  try {
    (void)samples(b, 0.1, 10);
    FAIL();
  } catch (const FrobError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("'throwsLogicError'"), std::string::npos) << m;
    EXPECT_NE(m.find("t = 0.300 s"), std::string::npos) << m;
    EXPECT_NE(m.find("student bug"), std::string::npos) << m;
  }
  Behavior<Wheels> c = runTask(idleRobot(), failAfter(0.5, "wall lost"));
  try {
    (void)samples(c, 0.1, 10);
    FAIL();
  } catch (const FrobError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("'failAfter'"), std::string::npos) << m;
    EXPECT_NE(m.find("wall lost"), std::string::npos) << m;
  }
}

TEST(Task, ANonFiniteOutputNamesTheTaskAndTheTime) {
  auto divides = []() { return mkTask([](const TaskState&) { return std::pair{wheels(1.0 / (0.4 - time()) * 0.0, 0), never()}; }); };
  auto seq = [&divides]() -> Task<Wheels> { co_await divides(); };
  try {
    (void)samples(runTask(idleRobot(), seq()), 0.1, 10);
    FAIL();
  } catch (const FrobError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("non-finite"), std::string::npos) << m;
    EXPECT_NE(m.find("t = 0.400 s"), std::string::npos) << m;
    EXPECT_NE(m.find("'lambda in "), std::string::npos) << m;  // the lambda that made the task
  }
}

TEST(Task, TheTimelineRecordsEveryTaskWithHowItEnded) {
  auto seq = []() -> Task<Wheels> {
    int n = co_await countTo(2);
    EXPECT_EQ(n, 2);
    try {
      co_await failAfter(0.1, "bumped");
    } catch (const RoboErr&) {
    }
  };
  Robot r = idleRobot();
  (void)samples(runTask(r, seq()), 0.1, 5);
  std::vector<TaskRecord> ended = r.debugChannel()->timeline().drainEnded();
  ASSERT_EQ(ended.size(), 3u);
  EXPECT_EQ(ended[0].name, "countTo");
  EXPECT_EQ(ended[0].how, TaskEnd::Returned);
  EXPECT_EQ(ended[0].detail, "2");
  EXPECT_NEAR(ended[0].end, 0.2, 1e-12);
  EXPECT_EQ(ended[0].depth, 1);
  EXPECT_EQ(ended[1].name, "failAfter");
  EXPECT_EQ(ended[1].how, TaskEnd::Failed);
  EXPECT_EQ(ended[1].detail, "error: bumped");
  EXPECT_EQ(ended[2].depth, 0);
  EXPECT_EQ(ended[2].how, TaskEnd::Returned);
  EXPECT_NE(ended[1].where.find("task_test.cpp:"), std::string::npos);
}

TEST(Task, AnObservedTimelineReplaysIntoAnIdenticalOne) {
  auto seq = []() -> Task<Wheels> {
    co_await countTo(2);
    co_await countTo(1);
  };
  Robot r = idleRobot();
  Timeline mirror;
  std::vector<TaskEnd> seen;
  r.debugChannel()->timeline().observe([&](const TaskRecord& t) {
    seen.push_back(t.how);
    if (t.how == TaskEnd::Running) {
      EXPECT_EQ(mirror.start(t.parent, t.name, t.where, t.start), t.id);
    } else {
      mirror.end(t.id, t.end, t.how, t.detail);
    }
  });
  (void)samples(runTask(r, seq()), 0.1, 5);
  // The outer task starts, then each inner one starts and returns in turn.
  EXPECT_EQ(seen,
            (std::vector<TaskEnd>{TaskEnd::Running, TaskEnd::Running, TaskEnd::Returned, TaskEnd::Running, TaskEnd::Returned, TaskEnd::Returned}));
  const std::deque<TaskRecord>& a = r.debugChannel()->timeline().ended();
  ASSERT_EQ(mirror.ended().size(), a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(mirror.ended()[k].name, a[k].name);
    EXPECT_EQ(mirror.ended()[k].depth, a[k].depth);
    EXPECT_EQ(mirror.ended()[k].end, a[k].end);
    EXPECT_EQ(mirror.ended()[k].detail, a[k].detail);
  }
}

Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(0.3, 0), predicate(frontSonar(r) < 50_cm)};
  });
}
Task<Wheels> turnLeft() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(0, 1.0), predicate(frontSonar(r) > 2.0)};
  });
}
Task<Wheels> runAround() {
  co_await goAhead();
  co_await turnLeft();
  co_await become(runAround());  // the paper's recursive runAround
}

TEST(Task, RecursiveRunAroundRunsAnHourInBoundedMemory) {
  long frames0 = liveTaskFrames();
  long nodes0 = liveNodeCount();
  KinematicRobot k(3.0);
  long maxFrames = 0, maxNodes = 0, laps = 0;
  double previous = 0;
  {
    Behavior<Wheels> c = runTask(k.robot(), runAround());
    k.run(c, 0.01, 3600.0, [&](const Instant& now, const Wheels& w) {
      if (now.step % 1000 == 0) {
        maxFrames = std::max(maxFrames, liveTaskFrames() - frames0);
        maxNodes = std::max(maxNodes, liveNodeCount() - nodes0);
      }
      if (w.turn > 0 && previous == 0) ++laps;
      previous = w.turn;
    });
    k.robot().debugChannel()->timeline().drainEnded();
  }
  EXPECT_GT(laps, 500);                  // it went round and round
  EXPECT_LE(maxFrames, 3);               // runAround and its current subtask (and the mkTask awaiting)
  EXPECT_LE(maxNodes, 60);               // one task's graph and the robot's sensors
  EXPECT_EQ(liveTaskFrames(), frames0);  // destroying the controller frees every frame
}

Task<Wheels> bugLike(int* restarts);
Task<Wheels> bugBody() {
  co_await forwardFor(0.2, 1.0);
  co_await failAfter(0.5, "wall lost");  // BUG's followWall losing the wall
}
// The paper's bug restarting itself from taskCatch's handler.
Task<Wheels> bugLike(int* restarts) {
  return taskCatch(bugBody(), [restarts](const RoboErr&) {
    ++*restarts;
    return bugLike(restarts);
  });
}

TEST(Task, ABugThatRestartsFromTaskCatchRunsAnHourInBoundedMemory) {
  long frames0 = liveTaskFrames();
  int restarts = 0;
  long maxFrames = 0;
  Robot r = idleRobot();
  Behavior<Wheels> c = runTask(r, bugLike(&restarts));
  Clock clock(0.01);
  for (int i = 0; i < 360'000; ++i) {
    (void)c.at(i == 0 ? clock.now() : clock.advance());
    if (i % 1000 == 0) {
      maxFrames = std::max(maxFrames, liveTaskFrames() - frames0);
      r.debugChannel()->timeline().drainEnded();
    }
  }
  EXPECT_EQ(restarts, 2399);  // one every 1.5 s for an hour
  EXPECT_LE(maxFrames, 5);
}

TEST(Task, SameInputsGiveTheSameOutputsAndTimelineBitForBit) {
  auto once = [] {
    KinematicRobot k(2.5, Pose2{Point2{0.3, -0.2}, 1.0});
    std::vector<Wheels> out;
    k.run(runTask(k.robot(), runAround()), 0.01, 60.0, [&out](const Instant&, const Wheels& w) { out.push_back(w); });
    std::vector<double> times;
    for (const TaskRecord& rec : k.robot().debugChannel()->timeline().drainEnded()) times.push_back(rec.end);
    return std::pair{out, times};
  };
  auto [a, ta] = once();
  auto [b, tb] = once();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Wheels)), 0);
  EXPECT_EQ(ta, tb);
  EXPECT_GT(ta.size(), 10u);
  // Repeats agree, and agree with pinned values, so that a change in what the run does (not only a
  // nondeterminism) shows: 30 tasks end, the first at step 661, the last at step 5999.
  EXPECT_EQ(ta.size(), 30u);
  EXPECT_EQ(ta.front(), 661 * 0.01);
  EXPECT_EQ(ta.back(), 5999 * 0.01);
}

TEST(Task, RunTaskFollowsTheFinalBehaviorAfterTheTaskEnds) {
  std::vector<Wheels> s = samples(runTask(TaskState(idleRobot()), forwardFor(1, 0.2), wheels(0, -1)), 0.1, 4);
  EXPECT_EQ(s[1], (Wheels{1, 0}));
  EXPECT_EQ(s[2], (Wheels{0, -1}));
}

template <class T>
Task<Wheels, T> give(T v) {
  return mkTask([v](const TaskState&) { return std::pair{wheels(0, 0), after(0.1).map([v] { return v; })}; });
}

// Issue 18: a task's result reads in the timeline as it reads in the program.
TEST(Task, TheTimelinePrintsAResultAsItsTypeReads) {
  auto seq = []() -> Task<Wheels> {
    (void)co_await give(true);
    (void)co_await give(Side::right);
    (void)co_await give(greenColour);
    (void)co_await give(Gap{1.5});
    (void)co_await give(Seen{3});
    (void)co_await give(std::optional<Side>());
    (void)co_await give(std::pair{Side::left, 2.5});
    (void)co_await give(std::tuple{1, std::string("two"), std::optional<int>(3)});
    (void)co_await give(std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9});
    (void)co_await give(std::variant<int, Side>(Side::right));
    (void)co_await give(Point2(3.0, -2.5));
    (void)co_await give(Outcome<std::string>{.value = "home"});
    (void)co_await give(Outcome<void>{.value = Unit{}});
    (void)co_await give(Outcome<int>{.error = RoboErr("lost the wall")});
  };
  Robot r = idleRobot();
  (void)samples(runTask(r, seq()), 0.1, 17);
  std::vector<std::string> details;
  for (const TaskRecord& rec : r.debugChannel()->timeline().drainEnded()) {
    if (rec.name == "give") details.push_back(rec.detail);
  }
  // Its operator<< if it has one (a bool's reads true); what a std type holds; an enum's type and
  // number; a withTask Outcome as it ended; else the type's name.
  EXPECT_EQ(details,
            (std::vector<std::string>{"true", "right", "Colour(1)", "Gap", "3 seen", "none", "(left, 2.5)", "(1, two, 3)",
                                      "[1, 2, 3, 4, 5, 6, 7, 8, ...]", "right", "(3, -2.5)", "returned home", "returned", "failed: lost the wall"}));
}

Task<Wheels> tick() {
  return mkTask([](const TaskState&) { return std::pair{wheels(0.1, 0), after(0.05)}; });
}
// The paper's `runAround = do ...; runAround`, written literally: the call is the last statement,
// but a C++ coroutine waits for it, so each call keeps its caller's frame.
Task<Wheels> tickForever() {
  co_await tick();
  co_await tickForever();
}

// Issue 15: today the literal form costs a frame per call for as long as it runs (72,000 frames
// after an hour at 20 calls a second). It now stops once 1,000 calls are nested, with a message
// showing the fix; frames never exceed that bound. Counted exactly with liveTaskFrames().
TEST(Task, TheLiteralRecursionStopsAtABoundWithItsFixInsteadOfGrowingForAnHour) {
  long frames0 = liveTaskFrames();
  Robot r = idleRobot();
  long maxFrames = 0;
  double stopped = -1;
  std::string failure;
  {
    RunningController c([](const Robot& robot) { return runTask(robot, tickForever()); }, r);
    Clock clock(0.05);  // one call per step: 20 a second
    for (int i = 0; i < 72'000; ++i) {
      const Instant& now = i == 0 ? clock.now() : clock.advance();
      (void)c.step(now);
      maxFrames = std::max(maxFrames, liveTaskFrames() - frames0);
      if (c.failed() && stopped < 0) {
        stopped = now.time;
        failure = c.failure();
      }
      if (i % 1000 == 0) r.debugChannel()->timeline().drainEnded();
    }
  }
  // Call k starts at t = 0.05 k, nested k deep; call 1000's tick would be 1001 deep.
  EXPECT_NEAR(stopped, 50.0, 1e-9);
  EXPECT_LE(maxFrames, detail::kMaxTaskDepth + 2);  // calls 0..1000 and the refused tick
  EXPECT_EQ(liveTaskFrames(), frames0);
  EXPECT_NE(failure.find("task 'tickForever' is running inside itself"), std::string::npos) << failure;
  EXPECT_NE(failure.find("co_await become(tickForever());"), std::string::npos) << failure;
}

// Issue 15, when a behavior starts. With the paper, a behavior starts when it is switched in: the
// untilB of the task that drives it, which is its first sample. So a behavior built in a parent
// task and first read by a later subtask starts with that subtask, not when it was built.
TEST(Task, ABehaviorBuiltInAParentStartsWithTheSubtaskThatFirstReadsIt) {
  auto seq = []() -> Task<Wheels> {
    Behavior<double> counted = integral(constant(1.0));  // built at t = 0
    Event<Unit> soon = after(0.3);
    Event<Unit> already = predicate(constant(true));
    co_await forwardFor(0.0, 0.5);
    co_await mkTask([counted, soon](const TaskState&) { return std::pair{wheels(counted, 1), soon}; });
    co_await mkTask([already](const TaskState&) { return std::pair{wheels(0, 2), already}; });
    co_await mkTask([counted](const TaskState&) { return std::pair{wheels(counted, 3), never()}; });
  };
  std::vector<Wheels> s = samples(runTask(idleRobot(), seq()), 0.1, 11);
  EXPECT_EQ(s[5], (Wheels{0, 1}));  // t = 0.5: the integral starts at zero, with its first reader
  EXPECT_NEAR(s[7].forward, 0.2, 1e-12);
  // The timer built at t = 0 ends the subtask 0.3 s after that subtask began (t = 0.8), and the
  // predicate first sampled then occurs at once (a condition already true at its start).
  EXPECT_EQ(s[7].turn, 1);
  EXPECT_EQ(s[8].turn, 3);
  // A behavior starts once: a later reader continues it (here from 0.3 at t = 0.8).
  EXPECT_NEAR(s[10].forward, 0.5, 1e-12);
}

// The end of each task of a tree, each named after what ends it, run on a kinematic robot at step `dt`.
std::vector<TaskRecord> rateTree(double dt) {
  auto tree = []() -> Task<Wheels> {
    co_await forwardFor(0.5, 1.0).named("timer");
    co_await mkTask([](const TaskState& ts) { return std::pair{wheels(0, 1.0), predicate(orientation(ts.robot()) > 1.0)}; }).named("predicate");
    co_await mkTask([](const TaskState&) {
      return std::pair{wheels(0.3, 0), every(0.02).filter([](std::int64_t k) { return k >= 25; }).map([] { return Unit{}; })};
    }).named("every");
    (void)co_await timeLimit(mkTask([](const TaskState&) { return std::pair{wheels(0.2, 0), never()}; }), 0.7).named("timeLimit");
    const Robot r = (co_await getTaskState()).robot();
    co_await withExit(predicate(frontSonar(r) < 1.0), mkTask([](const TaskState&) { return std::pair{wheels(0.4, 0), never()}; })).named("withExit");
  };
  KinematicRobot k(3.0);
  k.run(runTask(k.robot(), tree()), dt, 10.0);
  std::vector<TaskRecord> ended;
  for (TaskRecord& rec : k.robot().debugChannel()->timeline().drainEnded()) {
    if (rec.depth == 1) ended.push_back(std::move(rec));
  }
  return ended;
}

// Issue 15: the same task tree at 20 Hz and 200 Hz switches at the same times. Each switch is seen
// at the first step at or after it, so each is late by less than one 20 Hz step (0.05 s), and each
// task starts where the one before ended: the n-th switch may be up to n steps late.
TEST(Task, ATaskTreeSwitchesAtTheSameTimesAt20HzAnd200Hz) {
  std::vector<TaskRecord> slow = rateTree(0.05);
  std::vector<TaskRecord> fast = rateTree(0.005);
  ASSERT_EQ(slow.size(), 5u);
  ASSERT_EQ(fast.size(), slow.size());
  for (std::size_t n = 0; n < slow.size(); ++n) {
    EXPECT_EQ(slow[n].name, fast[n].name);
    EXPECT_NEAR(slow[n].end, fast[n].end, 0.05 * static_cast<double>(n + 1) + 1e-9) << slow[n].name;
  }
  // The exact times: 1 s, 1 rad at 1 rad/s, 0.5 s, 0.7 s, then the wall 1 m ahead.
  EXPECT_NEAR(fast[2].end, 2.5, 0.01);
  EXPECT_NEAR(fast[3].end, 3.2, 0.015);
}

}  // namespace
}  // namespace frob
