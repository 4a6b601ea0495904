// Issue 29, a student's compile: each assignment's reference solution compiled cold through
// `frob run` (an empty controller cache, the precompiled header in place), then run 0.01 s. Whole
// processes, wall time. Issue 52: beside them, a plain 15-line file of the standard library compiled
// by the same compiler into a module, and each solution's CPU time (all its processes') as a multiple
// of the plain file's (`x_plain`): a figure that holds on any machine, busy or not.
// Run by hand: build/tests/bench/compile_bench
#include "../app/run_frob.hpp"
#include "iterations.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

namespace frob::testing {
namespace {

// What a newcomer's first C++ file looks like: four everyday headers, a few lines of code.
constexpr const char* kPlainFile = R"(#include <cmath>
#include <functional>
#include <string>
#include <vector>

std::vector<std::function<double(double)>> steps() {
  return {[](double x) { return std::sqrt(x); }, [](double x) { return std::sin(x) * 2.0; }};
}

extern "C" double plain(double x) {
  std::string name = "plain";
  for (const auto& f : steps()) x = f(x);
  return x + static_cast<double>(name.size());
}
)";

// CPU seconds, user and system, of this process's children that have ended (and of theirs).
double childrenCpuSeconds() {
  rusage use{};
  getrusage(RUSAGE_CHILDREN, &use);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  return seconds(use.ru_utime) + seconds(use.ru_stime);
}

// Compiles the plain file into a module, as a controller is (-O0, position-independent, shared):
// its CPU seconds, or -1 when it failed.
double compilePlainSeconds(const std::filesystem::path& dir) {
  const double before = childrenCpuSeconds();
  const FrobResult r = runCommand(dir, {FROB_CONTROLLER_COMPILER, "-std=c++20", "-O0", "-fPIC", "-shared", "plain.cpp", "-o", "plain.so"});
  if (r.status != 0) return -1.0;
  return childrenCpuSeconds() - before;
}

// The plain file's compile CPU time on this machine, the median of five (of one in a smoke test), measured once.
double plainSeconds() {
  static const double seconds = [] {
    const std::filesystem::path dir = freshFolder("bench_compile_plain_reference");
    std::ofstream(dir / "plain.cpp") << kPlainFile;
    std::vector<double> times;
    for (int i = 0; i < bench::iterations(5); ++i) times.push_back(compilePlainSeconds(dir));
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
  }();
  return seconds;
}

void CompilePlainFile(benchmark::State& state) {
  const std::filesystem::path dir = freshFolder("bench_compile_plain");
  std::ofstream(dir / "plain.cpp") << kPlainFile;
  for (auto _ : state) {
    if (compilePlainSeconds(dir) < 0) return state.SkipWithError("the plain file did not compile");
  }
}
BENCHMARK(CompilePlainFile)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));

void CompileSolution(benchmark::State& state, const std::string& assignment) {
  const std::filesystem::path dir = freshFolder("bench_compile_" + assignment);
  const std::string solution = std::string(FROB_ASSIGNMENTS_DIR) + "/" + assignment + "/solution.cpp";
  double total = 0;
  for (auto _ : state) {
    std::filesystem::remove_all(dir / "cache");
    const double before = childrenCpuSeconds();
    const FrobResult r = runFrob(dir, {"run", solution, "--seconds", "0.01", "--quiet"}, (dir / "cache").string());
    total += childrenCpuSeconds() - before;
    if (r.status != 0) return state.SkipWithError(r.err.c_str());
  }
  const double plain = plainSeconds();
  if (plain <= 0) return state.SkipWithError("the plain file did not compile");
  state.counters["x_plain"] = total / static_cast<double>(state.iterations()) / plain;
}
BENCHMARK_CAPTURE(CompileSolution, wander, std::string("wander"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));
BENCHMARK_CAPTURE(CompileSolution, wall_follow, std::string("wall_follow"))
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(bench::iterations(3));
BENCHMARK_CAPTURE(CompileSolution, go_to_goal, std::string("go_to_goal"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));
BENCHMARK_CAPTURE(CompileSolution, parallel, std::string("parallel"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));
BENCHMARK_CAPTURE(CompileSolution, bug, std::string("bug"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));
BENCHMARK_CAPTURE(CompileSolution, multi_robot, std::string("multi_robot"))
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(bench::iterations(3));

}  // namespace
}  // namespace frob::testing
