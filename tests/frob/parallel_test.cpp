#include "frob/frob.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace frob {
namespace {

Robot idleRobot() { return Robot(nomadSpec(), ScriptedSensors{}); }

Task<Wheels> drive(double forward, double seconds) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, 0), after(seconds)}; });
}
Task<Wheels> forever(double forward) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, 0), never()}; });
}
Task<Wheels, int> turnFor(double turn, double seconds, int result) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(0, turn), after(seconds).map([result] { return result; })}; });
}
Wheels add(const Wheels& a, const Wheels& b) { return {a.forward + b.forward, a.turn + b.turn}; }

std::vector<Wheels> run(Task<Wheels> t, int steps) { return sample(runTask(idleRobot(), std::move(t)), 0.1, steps); }

TEST(Parallel, WithTaskShowsEachTheOthersOutputAndTheFirstsEnd) {
  std::optional<Outcome<int>> firstEnd;
  auto t = withTask(
      // The first turns, then ends with 7; it sees the second's output one step late.
      [](Behavior<Wheels> second) {
        return mkTask([second](const TaskState&) {
          return std::pair{lift([](const Wheels& s) { return Wheels{0, s.forward}; }, second), after(0.3).map([] { return 7; })};
        });
      },
      // The second copies the first's turn into its forward speed at once, until the first ends.
      [&firstEnd](Behavior<Wheels> first, Event<Outcome<int>> end) -> Task<Wheels> {
        firstEnd = co_await mkTask([first, end](const TaskState&) {
          return std::pair{lift([](const Wheels& f) { return Wheels{1 + f.turn, 0}; }, first), end};
        });
      });
  std::vector<Wheels> s = run(std::move(t), 5);
  // Step 0: first sees 0 (nothing before) and turns 0; second drives 1 + 0.
  // Step 1: first sees 1 and turns 1; second drives 1 + 1 = 2 at once. Step 2: 3.
  EXPECT_EQ(s[0].forward, 1);
  EXPECT_EQ(s[1].forward, 2);
  EXPECT_EQ(s[2].forward, 3);
  ASSERT_TRUE(firstEnd);
  EXPECT_TRUE(firstEnd->ok());
  EXPECT_EQ(*firstEnd->value, 7);
  EXPECT_EQ(s[3].forward, 0);  // the second ended at t = 0.3 when the first did: final output
}

// withTask's end event occurs once, at the instant the first task ended (0.3 s), the same for every
// observer: a subtask of the second that starts later (at 0.5 s) does not see it, whether or not
// an earlier subtask looked at the event when it occurred.
TEST(Parallel, WithTaskEndOccursAtTheFirstsEndWhoeverLookedBefore) {
  for (const bool glance : {false, true}) {
    std::optional<int> seen;
    auto t = withTask([](Behavior<Wheels>) { return drive(0, 0.3); },
                      [glance, &seen](Behavior<Wheels>, Event<Outcome<void>> end) -> Task<Wheels> {
                        // The first subtask ends at 0.5 s; glancing, it samples the end event each step.
                        Behavior<bool> heard = hold(false, end.as(true));
                        co_await mkTask([glance, heard](const TaskState&) {
                          return std::pair{wheels(glance ? lift([](bool h) { return h ? 1.0 : 1.0; }, heard) : Behavior<double>(1.0), 0), after(0.5)};
                        });
                        seen = co_await mkTask([end](const TaskState&) { return std::pair{wheels(2, 0), end.as(1) | after(0.3).as(2)}; });
                      });
    const std::vector<Wheels> s = run(std::move(t), 10);
    ASSERT_TRUE(seen) << "glance " << glance;
    EXPECT_EQ(*seen, 2) << "glance " << glance;  // its own timer ended it: the end had occurred before it began
    EXPECT_EQ(s[5].forward, 2);
    EXPECT_EQ(s[8].forward, 0);  // ended at 0.8 s
  }
}

// Reading the first task's output once it has ended is an error that names the task and the
// instants, never a silent default value.
TEST(Parallel, WithTaskReadingTheFirstsOutputAfterItsEndIsAnError) {
  auto t = withTask([](Behavior<Wheels>) { return drive(5.5, 0.3); },
                    [](Behavior<Wheels> first, Event<Outcome<void>>) {
                      return mkTask([first](const TaskState&) { return std::pair{first, after(1.0)}; });
                    });
  Behavior<Wheels> b = runTask(idleRobot(), Task<Wheels>(std::move(t)));
  std::string message;
  try {
    (void)sample(b, 0.1, 6);
  } catch (const FrobError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("withTask: task 'drive' ended at t = 0.300 s, and its output was read at t = 0.400 s"), std::string::npos) << message;
}

// Decided (frob/README.md, "Cases the paper leaves open"): the paper makes reading t1's output an
// error "after this event"; at the instant of its end it is still t1's last output, so
// snapshot(t1e, t1b) gives what t1 drove until it ended.
TEST(Parallel, WithTaskSnapshotOfTheFirstsOutputAtItsEndGivesItsLastOutput) {
  std::optional<double> last;
  auto t = withTask([](Behavior<Wheels>) { return drive(5.5, 0.3); },
                    [&last](Behavior<Wheels> first, Event<Outcome<void>> end) -> Task<Wheels> {
                      last = co_await mkTask([first, end](const TaskState&) {
                        return std::pair{wheels(1, 0), snapshot(end, first).map([](const auto& p) { return p.second.forward; })};
                      });
                    });
  (void)run(std::move(t), 6);
  EXPECT_EQ(last, 5.5);
}

// Issue 15: generic lambdas for both; the first's argument is then a Behavior<Wheels>.
TEST(Parallel, WithTaskTakesGenericLambdas) {
  auto t =
      withTask([](auto second) { return mkTask([second](const TaskState&) {
                                   return std::pair{second, after(0.2)};
                                 }); },
               [](auto first, auto end) {
                 return mkTask([first, end](const TaskState&) { return std::pair{wheels(first.map(&Wheels::forward) + 1.0, 0), end.as(Unit{})}; });
               });
  std::vector<Wheels> s = run(std::move(t), 3);
  EXPECT_EQ(s[0].forward, 1);  // the first echoes the second one step late: 0, then 1, ...
  EXPECT_EQ(s[1].forward, 2);
  EXPECT_EQ(s[2].forward, 0);  // the first ended at t = 0.2, and the second with it
}

TEST(Parallel, ParallelMergesOutputsAndWaitsForBoth) {
  std::pair<int, Unit> results;
  auto t = [&results]() -> Task<Wheels> { results = co_await parallel(turnFor(1, 0.4, 5), drive(2, 0.2), add); };
  std::vector<Wheels> s = run(t(), 6);
  EXPECT_EQ(s[0], (Wheels{2, 1}));  // both
  EXPECT_EQ(s[2], (Wheels{0, 1}));  // the first alone
  EXPECT_EQ(s[4], (Wheels{0, 0}));  // both ended
  EXPECT_EQ(results.first, 5);
}

Task<Wheels> failAt(double seconds) {
  return mkTaskE([seconds](const TaskState&) {
    return std::tuple{wheels(0, 1), never(), after(seconds).map([] { return RoboErr("branch broke"); })};
  });
}

TEST(Parallel, AnErrorInEitherBranchFailsTheParallel) {
  auto failing = mkTaskE([](const TaskState&) { return std::tuple{wheels(0, 1), never(), after(0.2).map([] { return RoboErr("branch broke"); })}; });
  std::string caught;
  auto t = [&]() -> Task<Wheels> {
    try {
      co_await parallel(std::move(failing), forever(1), add);
    } catch (const RoboErr& e) {
      caught = e.what();
    }
  };
  (void)run(t(), 4);
  EXPECT_NE(caught.find("branch broke"), std::string::npos) << caught;
}

TEST(Parallel, DisableEndsWithTheFirstToFinishAndAbortsTheOther) {
  std::variant<int, Unit> winner;
  long frames0 = liveTaskFrames();
  long during = 0;
  auto t = [&]() -> Task<Wheels> {
    winner = co_await disable(turnFor(1, 0.2, 9), forever(3), add);
    during = liveTaskFrames() - frames0;
    co_await forever(0);
  };
  std::vector<Wheels> s = run(t(), 4);
  EXPECT_EQ(s[0], (Wheels{3, 1}));
  EXPECT_EQ(winner.index(), 0u);
  EXPECT_EQ(std::get<0>(winner), 9);
  EXPECT_LE(during, 3);  // the aborted forever(3) is gone
  EXPECT_EQ(s[3], (Wheels{0, 0}));
}

TEST(Parallel, SyncLoopAlternatesForever) {
  std::vector<Wheels> s = run(syncLoop([] { return drive(1, 0.2); }, [] { return drive(2, 0.1); }), 7);
  std::vector<double> f;
  for (const Wheels& w : s) f.push_back(w.forward);
  EXPECT_EQ(f, (std::vector<double>{1, 1, 2, 1, 1, 2, 1}));
}

TEST(Parallel, AsyncLoopRunsEachQBesideTheRestOfTheLoop) {
  // P drives 1 for 0.2 s; each Q turns 1 for 0.3 s beside the loop, so Q's overlap.
  std::vector<Wheels> s = run(asyncLoop([] { return drive(1, 0.2); }, [] { return turnFor(1, 0.3, 0); }, add), 8);
  std::vector<double> turn;
  for (const Wheels& w : s) turn.push_back(w.turn);
  EXPECT_EQ(turn, (std::vector<double>{0, 0, 1, 1, 2, 1, 2, 1}));
}

Task<Wheels> throwsLogicError() {
  co_await drive(1, 0.3);
  throw std::logic_error("student bug");
}

// The message a run ends with when `t` is sampled for a second, or "" if it does not end.
std::string failureOf(Task<Wheels> t) {
  try {
    (void)run(std::move(t), 10);
  } catch (const FrobError& e) {
    return e.what();
  }
  return "";
}

// Issue 15: only a RoboErr is a robot error, in whichever branch it is thrown. A std::logic_error
// in a branch run beside another is a bug: taskCatch must not restart on it (BUG would hide it);
// it ends the run with its own message, the task that threw it and the time.
TEST(Parallel, AnExceptionInABranchKeepsItsKindAndEndsTheRun) {
  int restarts = 0;
  auto caught = [&restarts](const RoboErr&) {
    ++restarts;
    return forever(0);
  };
  std::vector<std::string> messages{
      failureOf(taskCatch(Task<Wheels>(parallel(throwsLogicError(), forever(1), add)), caught)),
      failureOf(taskCatch(Task<Wheels>(parallel(forever(1), throwsLogicError(), add)), caught)),
      failureOf(taskCatch(Task<Wheels>(disable(throwsLogicError(), forever(1), add)), caught)),
      failureOf(taskCatch(
          withTask([](Behavior<Wheels>) { return throwsLogicError(); }, [](Behavior<Wheels>, Event<Outcome<void>>) { return forever(2); }), caught)),
  };
  EXPECT_EQ(restarts, 0);
  for (const std::string& m : messages) {
    EXPECT_NE(m.find("task 'throwsLogicError' failed at t = 0.300 s"), std::string::npos) << m;
    EXPECT_NE(m.find("student bug"), std::string::npos) << m;
  }
}

TEST(Parallel, ARoboErrInABranchIsStillCaughtAsOne) {
  std::string caught;
  auto t = taskCatch(Task<Wheels>(parallel(failAt(0.2), forever(1), add)), [&caught](const RoboErr& e) {
    caught = e.what();
    return forever(0);
  });
  EXPECT_EQ(failureOf(std::move(t)), "");
  EXPECT_EQ(caught, "branch broke");  // the error itself, not a description of it
}

}  // namespace
}  // namespace frob
