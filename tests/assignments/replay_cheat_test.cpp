// A determined student's cheat, built for every assignment as the student would build it: record a
// good controller's wheel commands (the reference solution's) in every world handed out with the
// rubric, then submit a controller that never looks at its sonars, recognises its world (and, with
// several robots, itself) by where it starts, and replays the recording. It earns visible points;
// the hidden worlds are drawn from the instructor's secret, never handed out, so it must earn at most
// a third of the hidden points. (Before the hidden worlds were generated, it earned them all.)
#include "frob/worlds/simulation.hpp"
#include "frob/worlds/world_file.hpp"
#include "grade_assignment.hpp"

#include <gmock/gmock.h>

#include <cinttypes>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

// One robot's recorded run: where it started, what its sonars read first, and the wheels it was given at each step.
struct Recording {
  Point2 start;
  std::vector<double> sonar;
  std::vector<Wheels> wheels;
  std::string returned = "none";  // what it reported, and when: the cheat reports it then too
  double returnedAt = 1e9;
};

// The recordings of every robot in each visible world, from the longest wheel log of its runs.
std::vector<Recording> recordingsIn(const course::Rubric& rubric, const fs::path& logs) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(logs)) files.push_back(e.path());
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) { return fs::file_size(a) > fs::file_size(b); });
  std::vector<Recording> all;
  std::set<std::string> seen;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string line, check, world;
    std::size_t robots = 0;
    std::uint64_t seed = 0;
    std::map<std::size_t, std::pair<std::string, double>> returns;
    while (std::getline(in, line) && line != "wheels") {
      std::istringstream words(line);
      std::string key;
      std::size_t robot = 0;
      words >> key >> robot;
      if (key == "returned") std::getline(words >> std::ws, returns[robot].first);
      std::string at;
      if (key == "returned_at" && words >> at) returns[robot].second = std::strtod(at.c_str(), nullptr);  // hex: not for >>
      const std::size_t gap = line.find(' ');
      if (line.rfind("seed ", 0) == 0) seed = std::stoull(line.substr(gap + 1));
      if (line.rfind("check ", 0) == 0) check = line.substr(gap + 1);
      if (line.rfind("world ", 0) == 0) world = line.substr(gap + 1);
      if (line.rfind("robots ", 0) == 0) robots = std::stoul(line.substr(gap + 1));
    }
    const auto c = std::find_if(rubric.checks.begin(), rubric.checks.end(), [&](const course::Check& k) { return k.name == check; });
    if (c == rubric.checks.end()) continue;
    const auto ref = std::find_if(c->worlds.begin(), c->worlds.end(), [&](const course::WorldRef& w) { return w.name == world; });
    if (ref == c->worlds.end() || !seen.insert(world).second) continue;
    const worlds::WorldDef w = course::loadWorldRef(*ref).value();
    worlds::Simulation sim(w, {.dt = rubric.dt, .seed = seed});
    sim.sense();
    std::vector<Recording> mine(robots);
    for (std::size_t i = 0; i < robots; ++i) mine[i].start = w.robots[i].start.position, mine[i].sonar = sim.frame(i).sonar;
    for (const auto& [i, value] : returns) mine.at(i).returned = value.first, mine.at(i).returnedAt = value.second;
    while (std::getline(in, line)) {
      std::istringstream step(line);
      for (Recording& r : mine) {
        std::string f, t;
        step >> f >> t;
        r.wheels.push_back({std::strtod(f.c_str(), nullptr), std::strtod(t.c_str(), nullptr)});
      }
    }
    all.insert(all.end(), mine.begin(), mine.end());
  }
  return all;
}

// The cheat's source: the recordings as tables, and a controller that replays the one that starts nearest.
std::string cheatSource(const std::vector<Recording>& recordings, double dt) {
  std::string s = "#include <frob/frob.hpp>\n#include <cmath>\n#include <memory>\n#include <vector>\nusing namespace frob;\n";
  s += "struct Recording { double x, y; std::vector<double> sonar; std::vector<Wheels> wheels; const char* returned; double at; };\n";
  s += "static const std::vector<Recording> kRecordings = {\n";
  char buf[96];
  for (const Recording& r : recordings) {
    std::snprintf(buf, sizeof buf, "{%a, %a, {", r.start.x(), r.start.y());
    s += buf;
    for (double d : r.sonar) std::snprintf(buf, sizeof buf, "%a,", d), s += buf;
    s += "}, {";
    for (const Wheels& w : r.wheels) std::snprintf(buf, sizeof buf, "{%a, %a},", w.forward, w.turn), s += buf;
    std::snprintf(buf, sizeof buf, "}, \"%s\", %a},\n", r.returned.c_str(), r.returnedAt);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "%a", dt);
  // At the first instant: the recording that started nearest, its first sonar frame nearest among those.
  s += "};\n"
       "const Recording* recognise(const Point2& p, const std::vector<double>& sonar) {\n"
       "  const Recording* best = nullptr;\n"
       "  double bestScore = 1e300;\n"
       "  for (const Recording& r : kRecordings) {\n"
       "    double score = 100 * std::hypot(r.x - p.x(), r.y - p.y());\n"
       "    for (std::size_t i = 0; i < sonar.size() && i < r.sonar.size(); ++i) score += std::abs(sonar[i] - r.sonar[i]);\n"
       "    if (score < bestScore) bestScore = score, best = &r;\n"
       "  }\n"
       "  return best;\n"
       "}\n"
       "Task<Wheels, std::string> replay() {\n"
       "  TaskState ts = co_await getTaskState();\n"
       "  const Point2 p = ts.initialPlace();\n"
       "  auto chosen = std::make_shared<const Recording*>(nullptr);\n"
       "  co_return co_await mkTask([p, chosen](const TaskState& ts) {\n"
       "    Behavior<Wheels> w = lift([p, chosen](double t, const std::vector<double>& sonar) {\n"
       "      if (*chosen == nullptr) *chosen = recognise(p, sonar);\n"
       "      const auto k = static_cast<std::size_t>(std::llround(t / " +
       std::string(buf) +
       "));\n"
       "      return k < (*chosen)->wheels.size() ? (*chosen)->wheels[k] : Wheels{}; }, time(), sonars(ts.robot()));\n"
       "    Event<std::string> report = predicate(lift([chosen](double t) { return *chosen != nullptr && t >= (*chosen)->at; }, time()))\n"
       "        .map([chosen] { return std::string((*chosen)->returned); });\n"
       "    return std::pair{w, report};\n"
       "  });\n"
       "}\n"
       "FROB_CONTROLLER(replay, .summary = \"replays recorded wheels\");\n";
  return s;
}

class ReplayCheat : public ::testing::TestWithParam<const char*> {};

TEST_P(ReplayCheat, EarnsAtMostAThirdOfTheHiddenPoints) {
  const std::string assignment = GetParam();
  Result<course::Rubric> rubric = course::loadRubric(assignmentFile(assignment, "rubric.toml"));
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  const fs::path dir = fs::path(::testing::TempDir()) / ("replay_cheat_" + assignment);
  fs::remove_all(dir);
  fs::create_directories(dir);

  // Record the reference solution in every world file the rubric names, hidden checks' too, with
  // the seeds a student has (the worlds' own): the rubric as a student can run it.
  course::Rubric handedOut = rubric.value();
  for (course::Check& c : handedOut.checks) c.visibility = course::Visibility::Visible, c.secretSeeds = 0, c.generated.reset();
  std::erase_if(handedOut.checks, [](const course::Check& c) { return c.worlds.empty(); });
  course::GradeDef record{.rubric = handedOut, .assignment = assignment, .logs = dir / "logs"};
  record.compiler.cacheDir = FROB_TEST_CACHE_DIR;
  (void)course::grade(record, assignmentFile(assignment, "solution.cpp"));
  const std::vector<Recording> recordings = recordingsIn(handedOut, dir / "logs");
  ASSERT_FALSE(recordings.empty());
  std::ofstream(dir / "cheat.cpp") << cheatSource(recordings, rubric.value().dt);

  const course::Grade g = gradeFile(assignment, dir / "cheat.cpp");
  double visible = 0, visibleMax = 0, hidden = 0, hiddenMax = 0;
  for (const course::CheckGrade& c : g.checks) {
    (c.visibility == course::Visibility::Visible ? visible : hidden) += c.score;
    (c.visibility == course::Visibility::Visible ? visibleMax : hiddenMax) += c.points;
  }
  // The cheat works where it was recorded (the worlds are handed out, and a run repeats exactly):
  // in parallel's warehouses, which all start alike, only where the longest recording was made.
  EXPECT_GE(visible, visibleMax / 4) << "the cheat is broken, so the hidden score below proves nothing";
  ASSERT_GT(hiddenMax, 0);
  EXPECT_LE(hidden, hiddenMax / 3) << hidden << " of " << hiddenMax << " hidden points";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(EveryAssignment, ReplayCheat, ::testing::Values("wander", "wall_follow", "go_to_goal", "parallel", "bug", "multi_robot"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

}  // namespace
}  // namespace frob::testing
