// Issue 13, frob grade: one assignment of 10 runs of 60 s (five reference worlds, two seeds each),
// no video, after the compile; and a class of copies of one solution that differ in whitespace,
// compiled and graded two at a time. Run by hand for figures:
//   build/tests/bench/grade_bench --benchmark_min_time=5
//   FROB_BENCH_CLASS=200 build/tests/bench/grade_bench --benchmark_filter=Class   # the 200-submission figure
#include "frob/grade/grade.hpp"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>

namespace {

using namespace frob;
namespace fs = std::filesystem;

// A rubric of one check: the paper's runAround, wandering five worlds with two seeds each for 60 s.
const fs::path& assignment() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / "frob_grade_bench";
    fs::create_directories(d / "class");
    std::ofstream(d / "rubric.toml") << R"(title = "Wander"
seconds = 60
[[check]]
name = "wanders without touching a wall"
worlds = ["empty", "corridor", "maze", "obstacles", "office"]
seeds = [1, 2]
collisions = { max = 1000 }
clearance = { min = 0.0 }
)";
    return d;
  }();
  return dir;
}

course::GradeDef gradeDef() {
  course::GradeDef def{.rubric = course::loadRubric(assignment() / "rubric.toml").value(), .assignment = "wander"};
  def.compiler.cacheDir = assignment() / "cache";
  return def;
}

void OneSubmissionTenRuns(benchmark::State& state) {
  const course::GradeDef def = gradeDef();
  const fs::path solution = fs::path(FROB_EXAMPLES_DIR) / "01_run_around.cpp";
  (void)course::grade(def, solution);  // the compile, outside the timing
  for (auto _ : state) {
    const course::Grade g = course::grade(def, solution);
    if (!g.compileError.empty() || g.checks.at(0).runs.size() != 10) return state.SkipWithError("the grade went wrong");
  }
}

// A class of `n` copies of the solution, each with its own whitespace (so each compiles once).
void Class(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  std::ifstream in(fs::path(FROB_EXAMPLES_DIR) / "01_run_around.cpp");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<fs::path> submissions;
  for (int k = 0; k < n; ++k) {
    submissions.push_back(assignment() / "class" / ("student" + std::to_string(k) + ".cpp"));
    std::ofstream(submissions.back()) << text << std::string(static_cast<std::size_t>(k + 1), '\n');
  }
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(assignment() / "cache");  // compile included
    state.ResumeTiming();
    const std::vector<course::Grade> grades = course::gradeAll(gradeDef(), submissions, 2);
    if (grades.size() != static_cast<std::size_t>(n) || !grades.back().compileError.empty()) return state.SkipWithError("a grade went wrong");
  }
  state.counters["submissions"] = n;
}

BENCHMARK(OneSubmissionTenRuns)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Class)
    ->Arg(std::getenv("FROB_BENCH_CLASS") != nullptr ? std::atoi(std::getenv("FROB_BENCH_CLASS")) : 2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
