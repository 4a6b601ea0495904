// Cost of a task switch, and the per-step overhead of running a behavior inside a task.
#include "wall_follower.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace frob;
using namespace bench;

Robot benchRobot() { return Robot(nomadSpec(), ScriptedSensors{}); }

// A task that lasts one step of the benchmark's clock (one switch per step). Tasks start at their
// event's instant, so a shorter timer would chain many tasks within one step.
Task<Wheels> oneStep() {
  return mkTask([](const TaskState&) { return std::pair{wheels(0.1, 0.2), after(0.01)}; });
}

Task<Wheels> switchEveryStep() {
  for (;;) co_await oneStep();
}

// End of one atomic task -> the next task's first sample, including building its graph.
void BM_TaskSwitch(benchmark::State& state) {
  Behavior<Wheels> c = runTask(benchRobot(), switchEveryStep());
  Clock clock(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(c.at(clock.advance()));
}
BENCHMARK(BM_TaskSwitch);

Behavior<Wheels> typical(const Robot& r) {
  Behavior<double> front = frontSonar(r);
  Behavior<double> side = leftSonar(r);
  return wheels(clamp((front - 0.5) * 0.8, 0.0, 0.4), (0.6 - side) * 1.5 + 0.1 * derivative(side));
}

void BM_BareBehaviorStep(benchmark::State& state) {
  Robot r = benchRobot();
  Behavior<Wheels> c = typical(r);
  Clock clock(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(c.at(clock.advance()));
}
BENCHMARK(BM_BareBehaviorStep);

// The same behavior as the body of a running task that never ends.
void BM_BehaviorInTaskStep(benchmark::State& state) {
  Robot r = benchRobot();
  Behavior<Wheels> c = runTask(r, mkTask([](const TaskState& ts) { return std::pair{typical(ts.robot()), never()}; }));
  Clock clock(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(c.at(clock.advance()));
}
BENCHMARK(BM_BehaviorInTaskStep);

// The paper's wall follower, bare and as the behavior of a running task.
void BM_BareWallFollowerStep(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<Wheels> c = wallFollower(robot);
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    fillFrame(*frame, now.step);
    benchmark::DoNotOptimize(c.at(now));
  }
}
BENCHMARK(BM_BareWallFollowerStep);

void BM_WallFollowerInTaskStep(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<Wheels> c = runTask(robot, mkTask([](const TaskState& ts) { return std::pair{wallFollower(ts.robot()), never()}; }));
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    fillFrame(*frame, now.step);
    benchmark::DoNotOptimize(c.at(now));
  }
}
BENCHMARK(BM_WallFollowerInTaskStep);

}  // namespace
