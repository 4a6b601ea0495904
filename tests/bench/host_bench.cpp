// Issue 12, the controller host: what host costs a step (frames out, wheels back) against the
// same controllers sampled in this process, for 1, 2 and 4 robots in one host or a host per robot,
// spinning before sleeping or sleeping at once; and what starting a host costs (spawn, sandbox,
// exec, dlopen, first answer).
// Run by hand for figures:   build/tests/bench/host_bench --benchmark_min_time=2
// Each iteration is one step of the run; the overhead per step is Sandboxed/N minus InProcess/N.
#include "frob/run/host.hpp"
#include "frob/worlds/registry.hpp"

#include <benchmark/benchmark.h>
#include <dlfcn.h>

namespace {

using namespace frob;
namespace fs = std::filesystem;

// The paper's runAround (example 01): a typical controller, a few behaviors per robot.
const fs::path kModule = fs::path(FROB_EXAMPLE_MODULES) / "01_run_around.so";

// The empty room with one robot, or the arena with two (its first two) or four.
const worlds::WorldDef& world(int robots) {
  static const worlds::WorldDef one = *worlds::loadReferenceWorld("empty");
  static const worlds::WorldDef four = *worlds::loadReferenceWorld("arena");
  static const worlds::WorldDef two = [] {
    worlds::WorldDef w = four;
    w.robots.resize(2);
    return w;
  }();
  return robots == 1 ? one : robots == 2 ? two : four;
}

void perStep(benchmark::State& state, worlds::Run& run) {
  for (auto _ : state) run.step();
  if (!run.failures().empty()) state.SkipWithError(run.failures()[0].message.c_str());
}

void InProcess(benchmark::State& state) {
  void* handle = ::dlopen(kModule.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) return state.SkipWithError(::dlerror());
  using Entry = const ControllerEntry* (*)();
  const Controller make = reinterpret_cast<Entry>(::dlsym(handle, "frob_controller_v1"))()->make;
  worlds::Run run(world(static_cast<int>(state.range(0))), {}, {make}, {.keepSteps = false});
  perStep(state, run);
}

void Sandboxed(benchmark::State& state) {
  course::HostDef def{.robots = static_cast<std::uint32_t>(state.range(0)), .spinNanoseconds = static_cast<std::uint64_t>(state.range(1)) * 1000};
  Result<std::shared_ptr<course::ControllerHost>> host = course::ControllerHost::start({kModule}, {"run_around"}, def);
  if (!host) return state.SkipWithError(host.error().c_str());
  worlds::Run run(world(static_cast<int>(state.range(0))), {}, host.value()->driver({0}, false), {.keepSteps = false});
  perStep(state, run);
}

// A host of its own per robot, as frob run and frob grade drive a run.
void HostPerRobot(benchmark::State& state) {
  const worlds::WorldDef& w = world(static_cast<int>(state.range(0)));
  const course::HostDef def{.spinNanoseconds = static_cast<std::uint64_t>(state.range(1)) * 1000};
  Result<course::RobotHosts> hosts = course::RobotHosts::start({kModule}, {"run_around"}, {0}, w.robots.size(), def);
  if (!hosts) return state.SkipWithError(hosts.error().c_str());
  worlds::Run run(w, {}, hosts.value().driver(false), {.keepSteps = false});
  perStep(state, run);
}

void HostStart(benchmark::State& state) {
  for (auto _ : state) {
    Result<std::shared_ptr<course::ControllerHost>> host = course::ControllerHost::start({kModule}, {"run_around"});
    if (!host) return state.SkipWithError(host.error().c_str());
  }
}

BENCHMARK(InProcess)->ArgName("robots")->Arg(1)->Arg(2)->Arg(4);
// Args: robots, microseconds each side spins before it sleeps (0: sleeps at once, for shared cores).
BENCHMARK(Sandboxed)->ArgNames({"robots", "spin_us"})->Args({1, 50})->Args({4, 50})->Args({1, 0})->Args({4, 0});
BENCHMARK(HostPerRobot)->ArgNames({"robots", "spin_us"})->Args({1, 50})->Args({2, 50})->Args({4, 50})->Args({4, 0});
BENCHMARK(HostStart)->Unit(benchmark::kMillisecond);

}  // namespace
