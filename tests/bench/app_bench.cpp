// The frob command as a user meets it (issue 7): compiling a single-file controller (target <= 5 s),
// running it again from the cache (no compile), and the README's first command, the BUG demo with
// its video (target <= 10 s). Whole processes, wall time. Run by hand: build/tests/bench/app_bench
#include "../app/run_frob.hpp"
#include "iterations.hpp"

#include <benchmark/benchmark.h>

namespace frob::testing {
namespace {

const char* kController = R"(#include <frob/frob.hpp>
using namespace frob;
using namespace frob::literals;
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(30_cm, 0), predicate(frontSonar(ts.robot()) < 60_cm)}; });
}
Task<Wheels> turnLeft() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0, 0.8), predicate(frontSonar(ts.robot()) > 1.5)}; });
}
Task<Wheels> wander() { for (;;) { co_await goAhead(); co_await turnLeft(); } }
FROB_CONTROLLER(wander)
)";

// Compiles into an empty cache each time, then runs 0.1 s.
void BM_CompileController(benchmark::State& state) {
  const std::filesystem::path dir = freshFolder("bench_compile");
  std::ofstream(dir / "wander.cpp") << kController;
  for (auto _ : state) {
    std::filesystem::remove_all(dir / "cache");
    const FrobResult r = runFrob(dir, {"run", "wander.cpp", "--seconds", "0.1", "--quiet"}, (dir / "cache").string());
    if (r.status != 0) return state.SkipWithError(r.err.c_str());
  }
}
BENCHMARK(BM_CompileController)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));

// The same file again: found in the cache, loaded, run 0.1 s.
void BM_CachedController(benchmark::State& state) {
  const std::filesystem::path dir = freshFolder("bench_cached");
  std::ofstream(dir / "wander.cpp") << kController;
  const std::string cache = (dir / "cache").string();
  if (runFrob(dir, {"run", "wander.cpp", "--seconds", "0.1", "--quiet"}, cache).status != 0) return state.SkipWithError("compile failed");
  for (auto _ : state) {
    const FrobResult r = runFrob(dir, {"run", "wander.cpp", "--seconds", "0.1", "--quiet"}, cache);
    if (r.status != 0) return state.SkipWithError(r.err.c_str());
  }
}
BENCHMARK(BM_CachedController)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(bench::iterations(5));

// `frob run` with no arguments: BUG in the obstacle field, simulated and written to bug.mp4.
void BM_Demo(benchmark::State& state) {
  const std::filesystem::path dir = freshFolder("bench_demo");
  for (auto _ : state) {
    const FrobResult r = runFrob(dir, {"run", "--quiet"});
    if (r.status != 0) return state.SkipWithError(r.err.c_str());
  }
}
BENCHMARK(BM_Demo)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(bench::iterations(3));

}  // namespace
}  // namespace frob::testing
