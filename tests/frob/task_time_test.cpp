// A task's clock (issue 50): a task and its timers start at the instant of the event that started
// it, which may fall between two samples, so timing does not drift with the number of tasks or the
// step; and its local time counts whole steps, so that time() and after() agree exactly.
#include "frob/frob.hpp"
#include "kinematic_robot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace frob {
namespace {

using testing::KinematicRobot;

Robot idleRobot() { return Robot(nomadSpec(), ScriptedSensors{}); }

// Drives at `speed` for `seconds`, measured by after().
Task<Wheels> forwardFor(double speed, double seconds) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(speed, 0), after(seconds)}; });
}

Task<Wheels> tenTimes(double seconds) {
  for (int k = 0; k < 10; ++k) co_await forwardFor(0.5, seconds);
}

// The time of the first sample at which the run drives no more (its final behavior), and the
// distance the robot drove until then.
struct End {
  double time = -1;
  double distance = 0;
};
End endOf(Task<Wheels> t, double dt) {
  KinematicRobot k;
  End end;
  k.run(runTask(k.robot(), std::move(t)), dt, 3.0, [&end](const Instant& now, const Wheels& w) {
    if (w.forward == 0 && end.time < 0) end.time = now.time;
  });
  end.distance = k.pose().position.norm();
  return end;
}

// The figures: ten after(0.1) took 1.00 / 1.20 / 1.40 s at dt 0.01 / 0.03 / 0.07 and the
// robot went 0.49 / 0.58 / 0.69 m. Now the sequence ends at the first sample at or after 1 s, less
// than a step late, and the robot drives 0.5 m/s until that sample: 0.5 m plus at most half a step's
// 0.5 m/s. (The bounds allow 1e-9 s of rounding in the sum of the times.)
TEST(TaskTime, TimedTasksInSequenceEndWithinOneStepOfTheSumOfTheirTimesAtAnyStep) {
  for (double dt : {0.01, 0.03, 0.07, 0.002}) {
    End end = endOf(tenTimes(0.1), dt);
    EXPECT_GE(end.time, 1.0 - 1e-9) << "dt " << dt;
    EXPECT_LT(end.time, 1.0 + dt - 1e-9) << "dt " << dt;
    EXPECT_GE(end.distance, 0.5 - 1e-9) << "dt " << dt;
    EXPECT_LT(end.distance, 0.5 + 0.5 * dt) << "dt " << dt;
  }
}

// Ten after(0.015) at the default step took 0.20 s, not 0.15: every task started a sample late.
TEST(TaskTime, TimersShorterThanTheStepDoNotAddUp) {
  for (double dt : {0.01, 0.03, 0.07, 0.002}) {
    End end = endOf(tenTimes(0.015), dt);
    EXPECT_GE(end.time, 0.15 - 1e-9) << "dt " << dt;
    EXPECT_LT(end.time, 0.15 + dt - 1e-9) << "dt " << dt;
  }
}

// A task that ends on predicate(time() >= 1) under timeLimit(1) ends in time from every start
// instant: its time() reads exactly 1 at 100 steps of 0.01 s (not 0.99999999999999956, as the
// difference of two clock readings did), when its timeLimit's after(1) occurs too; and at steps
// that do not divide a second, both occur at the same sample. A tie goes to the task's own exit.
TEST(TaskTime, TimeAndTimersAgreeExactlyFromEveryStartInstant) {
  for (double dt : {0.01, 0.03, 0.07, 0.002}) {
    for (double wait : {0.0, 0.16, 0.41, 0.67, 0.92, 1.13}) {
      std::optional<bool> inTime;
      double readAtEnd = -1;
      auto seq = [&]() -> Task<Wheels> {
        co_await forwardFor(0, wait);
        auto untilOne = mkTask([&readAtEnd](const TaskState&) {
          Behavior<double> t = time();
          return std::pair{wheels(0, 0), snapshot(predicate(t >= 1.0), t).map([&readAtEnd](const auto& p) {
                             readAtEnd = p.second;
                             return Unit{};
                           })};
        });
        inTime = co_await timeLimit(std::move(untilOne), 1.0);
      };
      (void)sample(runTask(idleRobot(), seq()), dt, static_cast<std::int64_t>(3.0 / dt));
      ASSERT_TRUE(inTime) << "dt " << dt << ", start " << wait;
      EXPECT_TRUE(*inTime) << "dt " << dt << ", start " << wait;
      EXPECT_LT(readAtEnd, 1.0 + dt) << "dt " << dt << ", start " << wait;
      if (dt == 0.01 || dt == 0.002) EXPECT_EQ(readAtEnd, 1.0) << "dt " << dt << ", start " << wait;
    }
  }
}

// A task started by a timer due between samples (0.25 s, sampled at 0.3 s) starts at 0.25 s: its
// time(), its integral of 1 and its state's startTime say so at its first sample, and its own
// timers count from there.
TEST(TaskTime, ATaskStartedBetweenSamplesStartsAtTheEventsInstant) {
  std::vector<Wheels> out;
  double startTime = -1;
  auto seq = [&startTime]() -> Task<Wheels> {
    co_await forwardFor(0, 0.25);
    startTime = (co_await getTaskState()).startTime();
    co_await mkTask([](const TaskState&) { return std::pair{wheels(time(), integral(constant(1.0))), after(0.2)}; });
  };
  out = sample(runTask(idleRobot(), seq()), 0.1, 6);
  EXPECT_NEAR(startTime, 0.25, 1e-12);
  EXPECT_NEAR(out[3].forward, 0.05, 1e-12);
  EXPECT_NEAR(out[3].turn, 0.05, 1e-12);
  EXPECT_NEAR(out[4].forward, 0.15, 1e-12);
  EXPECT_NEAR(out[4].turn, 0.15, 1e-12);
  EXPECT_EQ(out[5].forward, 0.0);  // its after(0.2) was due at 0.45 s: ended at the sample 0.5 s
}

}  // namespace
}  // namespace frob
