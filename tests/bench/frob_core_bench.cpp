// Per-step cost of a Frob controller graph against the same algorithm hand-written in plain C++,
// and the cost of a switch and of building a task-sized graph.
#include "wall_follower.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace frob;
using namespace bench;

void BM_FrobWallFollowerStep(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<Wheels> controller = wallFollower(robot);
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    fillFrame(*frame, now.step);
    benchmark::DoNotOptimize(controller.at(now));
  }
  state.counters["nodes"] = static_cast<double>(liveNodeCount());
}
BENCHMARK(BM_FrobWallFollowerStep);

void BM_HandWrittenWallFollowerStep(benchmark::State& state) {
  SensorFrame frame;
  HandWritten controller;
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    fillFrame(frame, now.step);
    benchmark::DoNotOptimize(controller.step(frame, now.time));
  }
}
BENCHMARK(BM_HandWrittenWallFollowerStep);
// Both again for a fixed number of steps, so that instruction counts (valgrind --tool=callgrind,
// which counts independent of load) compare between builds and between the two:
//   valgrind --tool=callgrind build/tests/bench/frob_core_bench --benchmark_filter=FrobWallFollowerFixedSteps
BENCHMARK(BM_FrobWallFollowerStep)->Name("FrobWallFollowerFixedSteps")->Iterations(100000);
BENCHMARK(BM_HandWrittenWallFollowerStep)->Name("HandWrittenWallFollowerFixedSteps")->Iterations(100000);

// The same graph, built fresh each iteration: the cost of creating a task-sized graph.
void BM_BuildWallFollowerGraph(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  for (auto _ : state) benchmark::DoNotOptimize(wallFollower(robot));
}
BENCHMARK(BM_BuildWallFollowerGraph);

// One untilB firing per iteration: a switch to a freshly built behavior, then its first sample.
Behavior<double> flipper() { return untilB(time(), after(0.005).map([] { return flipper(); })); }

void BM_UntilBSwitch(benchmark::State& state) {
  Behavior<double> b = flipper();  // at dt = 0.01 each copy's timer fires at its second sample: one switch per step
  Clock clock(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(b.at(clock.advance()));
}
BENCHMARK(BM_UntilBSwitch);

}  // namespace
