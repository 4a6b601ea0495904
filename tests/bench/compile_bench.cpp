// Issue 29, a student's compile: each assignment's reference solution compiled cold through
// `frob run` (an empty controller cache, the precompiled header in place; target <= 1 s each), then
// run 0.01 s. Whole processes, wall time. Run by hand: build/tests/bench/compile_bench
#include "../app/run_frob.hpp"

#include <benchmark/benchmark.h>

namespace frob::testing {
namespace {

void CompileSolution(benchmark::State& state, const std::string& assignment) {
  const std::filesystem::path dir = freshFolder("bench_compile_" + assignment);
  const std::string solution = std::string(FROB_ASSIGNMENTS_DIR) + "/" + assignment + "/solution.cpp";
  for (auto _ : state) {
    std::filesystem::remove_all(dir / "cache");
    const FrobResult r = runFrob(dir, {"run", solution, "--seconds", "0.01", "--quiet"}, (dir / "cache").string());
    if (r.status != 0) return state.SkipWithError(r.err.c_str());
  }
}
BENCHMARK_CAPTURE(CompileSolution, wander, std::string("wander"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(CompileSolution, wall_follow, std::string("wall_follow"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(CompileSolution, go_to_goal, std::string("go_to_goal"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(CompileSolution, parallel, std::string("parallel"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(CompileSolution, bug, std::string("bug"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(CompileSolution, multi_robot, std::string("multi_robot"))->Unit(benchmark::kSecond)->UseRealTime()->Iterations(3);

}  // namespace
}  // namespace frob::testing
