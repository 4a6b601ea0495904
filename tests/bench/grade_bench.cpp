// Issue 13, frob grade: one assignment of 10 runs of 60 s (five reference worlds, two seeds each),
// no video, after the compile; and a class of distinct submissions of an assignment, compiled and
// graded two at a time. Run by hand for figures:
//   build/tests/bench/grade_bench --benchmark_min_time=5
//   FROB_BENCH_CLASS=200 build/tests/bench/grade_bench --benchmark_filter=Class   # the 200-submission figure
//   FROB_BENCH_ASSIGNMENT=bug FROB_BENCH_CLASS=200 build/tests/bench/grade_bench --benchmark_filter=Class
#include "frob/grade/grade.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <regex>
#include <set>
#include <sstream>

namespace {

using namespace frob;
namespace fs = std::filesystem;

// A rubric of one check: the paper's runAround, wandering five worlds with two seeds each for 60 s.
const fs::path& assignment() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / "frob_grade_bench";
    fs::create_directories(d);
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

// A class of `n` distinct submissions of one assignment (go_to_goal, or FROB_BENCH_ASSIGNMENT), as
// students' files differ: submission k is the k-th of the assignment's solution, starter and wrong
// submissions (tests/assignments/<name>/), round after round, with one decimal number of its code
// changed by a few percent (number k / sources, by 1% more each time it comes round again). Graded as an
// instructor grades a class, hidden checks included (a benchmark secret), compile included, two at a
// time. Its counters split the jobs' seconds between the runs and the rest (mostly the compiles).
std::vector<std::string> distinctSubmissions(const std::string& assignment, int n) {
  std::vector<std::string> sources;
  const auto read = [&](const fs::path& file) {
    std::ifstream in(file);
    sources.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  read(fs::path(FROB_ASSIGNMENTS_DIR) / assignment / "solution.cpp");
  read(fs::path(FROB_ASSIGNMENTS_DIR) / assignment / "starter.cpp");
  std::vector<fs::path> wrong;
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(FROB_WRONG_DIR) / assignment)) wrong.push_back(e.path());
  std::sort(wrong.begin(), wrong.end());
  for (const fs::path& w : wrong) read(w);

  static const std::regex decimal(R"((\b\d+\.\d+)\b)");
  std::set<std::string> seen;
  std::vector<std::string> out;
  for (int k = 0; static_cast<int>(out.size()) < n; ++k) {
    const std::string& text = sources[static_cast<std::size_t>(k) % sources.size()];
    const auto round = static_cast<std::size_t>(k) / sources.size();
    std::vector<std::smatch> numbers;  // those of the code, not of comments, and not zero (a change of it shows)
    for (auto it = std::sregex_iterator(text.begin(), text.end(), decimal); it != std::sregex_iterator(); ++it) {
      const auto at = static_cast<std::size_t>(it->position());
      const std::size_t line = text.rfind('\n', at) + 1;  // 0 on the first line
      if (std::stod(it->str()) != 0.0 && text.substr(line, at - line).find("//") == std::string::npos) numbers.push_back(*it);
    }
    if (numbers.empty()) throw std::runtime_error("a source without a decimal number to edit");
    const std::smatch& m = numbers[round % numbers.size()];
    const double factor = 1.0 + 0.01 * static_cast<double>(1 + round / numbers.size());
    std::ostringstream edited;
    edited << text.substr(0, static_cast<std::size_t>(m.position())) << std::setprecision(6) << std::showpoint << std::stod(m.str()) * factor
           << text.substr(static_cast<std::size_t>(m.position() + m.length()));
    if (seen.insert(edited.str()).second) out.push_back(edited.str());
  }
  return out;
}

void Class(benchmark::State& state) {
  const char* chosen = std::getenv("FROB_BENCH_ASSIGNMENT");
  const std::string assignment = chosen != nullptr ? chosen : "go_to_goal";
  const fs::path dir = fs::temp_directory_path() / "frob_grade_bench" / ("class_" + assignment);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<fs::path> submissions;
  for (const std::string& text : distinctSubmissions(assignment, static_cast<int>(state.range(0)))) {
    submissions.push_back(dir / ("student" + std::to_string(submissions.size()) + ".cpp"));
    std::ofstream(submissions.back()) << text;
  }
  course::GradeDef def{.rubric = course::loadRubric(fs::path(FROB_ASSIGNMENTS_DIR) / assignment / "rubric.toml").value(),
                       .assignment = assignment,
                       .secret = "bench-secret"};
  def.compiler.cacheDir = dir / "cache";
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(def.compiler.cacheDir);  // compile and the hidden worlds' check included
    state.ResumeTiming();
    const std::vector<course::Grade> grades = course::gradeAll(def, submissions, 2);
    double graded = 0.0, runs = 0.0;  // a job's seconds on each grade, and on its runs
    for (const course::Grade& g : grades) {
      if (!g.compileError.empty()) return state.SkipWithError(("a submission did not compile: " + g.compileError).c_str());
      graded += g.wallSeconds;
      for (const course::CheckGrade& c : g.checks) {
        for (const course::RunGrade& r : c.runs) runs += r.wallSeconds;
      }
    }
    // Where the jobs' time went: their runs, and the rest (mostly compiles), in seconds of a job.
    state.counters["runs_s"] = runs;
    state.counters["compiles_s"] = graded - runs;
  }
  state.counters["submissions"] = static_cast<double>(submissions.size());
}

BENCHMARK(OneSubmissionTenRuns)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(Class)
    ->Arg(std::getenv("FROB_BENCH_CLASS") != nullptr ? std::atoi(std::getenv("FROB_BENCH_CLASS")) : 2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
