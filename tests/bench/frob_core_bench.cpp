// Per-step cost of a Frob controller graph against the same algorithm hand-written in plain C++,
// and the cost of a switch and of building a task-sized graph.
//
// Two pairs: whole iterations (the sensor frame filled with three sin/cos and a vector assign,
// then the controller), and the controller alone (the frame's three changing readings stored from
// a table made beforehand, the same three stores on both sides). The reporter prints both, and the
// controller's overhead as a share of a one-robot simulator step (the maze, 16 sonars of 5 rays).
// Run by hand for figures:
//   build/tests/bench/frob_core_bench --benchmark_repetitions=5
#include "cpu_figures.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "wall_follower.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <string>

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
// The readings fillFrame() gives at steps 1..kTable, computed once, so that a step of the
// controller-only pair costs three stores besides the controller.
constexpr std::size_t kTable = 4096;
struct Readings {
  double left, front, velocity;
};
const std::array<Readings, kTable>& readings() {
  static const std::array<Readings, kTable> table = [] {
    std::array<Readings, kTable> t{};
    SensorFrame f;
    for (std::size_t k = 0; k < kTable; ++k) {
      fillFrame(f, static_cast<std::int64_t>(k + 1));
      t[k] = {f.sonar[4], f.sonar[0], f.velocity};
    }
    return t;
  }();
  return table;
}
inline void store(SensorFrame& f, std::int64_t step) {
  const Readings& r = readings()[static_cast<std::size_t>(step - 1) % kTable];
  f.sonar[4] = r.left, f.sonar[0] = r.front, f.velocity = r.velocity;
}

void BM_FrobWallFollowerControllerOnly(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  fillFrame(*frame, 0);
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  Behavior<Wheels> controller = wallFollower(robot);
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    store(*frame, now.step);
    benchmark::DoNotOptimize(controller.at(now));
  }
}
BENCHMARK(BM_FrobWallFollowerControllerOnly);

void BM_HandWrittenWallFollowerControllerOnly(benchmark::State& state) {
  SensorFrame frame;
  fillFrame(frame, 0);
  HandWritten controller;
  Clock clock(0.01);
  for (auto _ : state) {
    const Instant& now = clock.advance();
    store(frame, now.step);
    benchmark::DoNotOptimize(controller.step(frame, now.time));
  }
}
BENCHMARK(BM_HandWrittenWallFollowerControllerOnly);

// One step of the simulator with one robot: the cost a controller's overhead is set against.
void BM_OneRobotSimulatorStep(benchmark::State& state) {
  frob::worlds::Simulation sim(*frob::worlds::loadReferenceWorld("maze"));
  if (sim.robotCount() != 1) state.SkipWithError("the maze was expected to hold one robot");
  const std::vector<Wheels> wheels(sim.robotCount(), Wheels{.forward = 0.3, .turn = 0.2});
  for (auto _ : state) {
    sim.sense();
    sim.step(wheels);
  }
}
BENCHMARK(BM_OneRobotSimulatorStep);

// Both again for a fixed number of steps, so that instruction counts (valgrind --tool=callgrind,
// which counts independent of load) compare between builds and between the two:
//   valgrind --tool=callgrind build/tests/bench/frob_core_bench --benchmark_filter=FrobWallFollowerFixedSteps
// (add --toggle-collect='*BM_FrobWallFollowerControllerOnly*' and the like to count one benchmark's
// function only; divide by its iterations for a step).
BENCHMARK(BM_FrobWallFollowerStep)->Name("FrobWallFollowerFixedSteps")->Iterations(100000);
BENCHMARK(BM_HandWrittenWallFollowerStep)->Name("HandWrittenWallFollowerFixedSteps")->Iterations(100000);
BENCHMARK(BM_FrobWallFollowerControllerOnly)->Name("FrobControllerOnlyFixedSteps")->Iterations(100000);
BENCHMARK(BM_HandWrittenWallFollowerControllerOnly)->Name("HandWrittenControllerOnlyFixedSteps")->Iterations(100000);
BENCHMARK(BM_OneRobotSimulatorStep)->Name("OneRobotSimulatorFixedSteps")->Iterations(2000);

// The same graph, built fresh each iteration: the cost of creating a task-sized graph.
void BM_BuildWallFollowerGraph(benchmark::State& state) {
  auto frame = std::make_shared<SensorFrame>();
  Robot robot(nomadSpec(), std::shared_ptr<const SensorFrame>(frame));
  for (auto _ : state) benchmark::DoNotOptimize(wallFollower(robot));
}
BENCHMARK(BM_BuildWallFollowerGraph);

// One untilB firing per iteration: a switch to a freshly built behavior, then its first sample.
Behavior<double> flipper() {
  return untilB(time(), after(0.005).map([] { return flipper(); }));
}

void BM_UntilBSwitch(benchmark::State& state) {
  Behavior<double> b = flipper();  // at dt = 0.01 each copy's timer fires at its second sample: one switch per step
  Clock clock(0.01);
  for (auto _ : state) benchmark::DoNotOptimize(b.at(clock.advance()));
}
BENCHMARK(BM_UntilBSwitch);

// Prints the usual table, then both pairs and the controller's overhead against a simulator step.
class OverheadReporter : public bench::CpuFiguresReporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    auto ns = [&](const char* name) { return seconds(name) < 0 ? -1.0 : seconds(name) * 1e9; };
    const double frob = ns("BM_FrobWallFollowerStep"), hand = ns("BM_HandWrittenWallFollowerStep");
    const double frobOnly = ns("BM_FrobWallFollowerControllerOnly"), handOnly = ns("BM_HandWrittenWallFollowerControllerOnly");
    const double sim = ns("BM_OneRobotSimulatorStep");
    if (frob < 0 || hand < 0 || frobOnly < 0 || handOnly < 0 || sim < 0) return;
    std::printf("\nWall follower per step (CPU time), Frob against hand-written:\n");
    std::printf("  with the sensor-frame fill:  %7.1f ns vs %7.1f ns  (%.2fx)\n", frob, hand, frob / hand);
    std::printf("  controller only:             %7.1f ns vs %7.1f ns  (%.2fx, %.1f ns more)\n", frobOnly, handOnly, frobOnly / handOnly,
                frobOnly - handOnly);
    std::printf("  that overhead is %.2f%% of a one-robot simulator step (%.1f us)\n", 100.0 * (frobOnly - handOnly) / sim, sim / 1e3);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  OverheadReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
