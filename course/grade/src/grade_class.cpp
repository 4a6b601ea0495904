// Grading a class: its submissions found and sharded, graded a few at a time; and the pieces a
// report needs around one grade (its assignment's rubric, a film of a run).
#include "frob/base/layout.hpp"
#include "frob/grade/grade.hpp"
#include "frob/grade/wheel_log.hpp"
#include "frob/run/controller_file.hpp"
#include "frob/run/format.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/world_file.hpp"
#include "runs.hpp"

#include <algorithm>
#include <atomic>
#include <cinttypes>
#include <fstream>
#include <mutex>
#include <thread>

namespace frob::course {

namespace fs = std::filesystem;

std::vector<Grade> gradeAll(GradeDef def, const std::vector<fs::path>& submissions, int jobs,
                            const std::function<void(std::size_t, std::size_t)>& progress, const ClassHooks& hooks) {
  jobs = std::clamp(jobs, 1, std::max<int>(1, static_cast<int>(submissions.size())));
  std::vector<Grade> grades(submissions.size());
  // The hidden worlds are checked once for the class, before its runs take cores; where that fails,
  // each grade says why.
  const Result<KeptWorlds> kept = submissions.empty() ? KeptWorlds{} : detail::hiddenWorldsOf(def);
  // Each run is the grader and a host per robot, taking turns. With two cores a run they spin while
  // they wait, and a step's handover costs nothing; runs that share the cores so would take them from
  // each other at every step, so then each run holds a core of its own, where its hosts sleep while
  // the grader simulates (the same in every run of the class; compiles overlap, anywhere).
  if (auto cores = std::make_shared<RunCores>(); 2 * static_cast<std::size_t>(jobs) > cores->size()) {
    def.runCores = std::move(cores);
    def.host.hostSpinNanoseconds = 0;
  }
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex told;
  const auto work = [&] {
    for (std::size_t k; (k = next++) < submissions.size();) {
      if (hooks.logs) {
        GradeDef own = def;
        own.logs = hooks.logs(k);
        grades[k] = detail::gradeWith(own, submissions[k], kept);
      } else {
        grades[k] = detail::gradeWith(def, submissions[k], kept);
      }
      if (hooks.graded) hooks.graded(k, grades[k]);
      const std::lock_guard<std::mutex> lock(told);
      if (progress) progress(++done, submissions.size());
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < jobs; ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  return grades;
}

std::vector<fs::path> submissionsIn(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    // Links and special files are listed, never followed: compiling one refuses it and says why.
    const fs::file_status st = e.symlink_status(ec);
    if (!fs::is_directory(st)) {
      if (e.path().extension() == ".cpp" || fs::is_symlink(st)) found.push_back(e.path());
      continue;
    }
    for (const fs::directory_entry& f : fs::directory_iterator(e.path(), ec)) {
      if (!fs::is_directory(f.symlink_status(ec)) && f.path().extension() == ".cpp") {
        found.push_back(e.path());
        break;
      }
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

fs::path submissionOf(const fs::path& file) {
  std::error_code ec;
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (companionsOf(file).empty()) return file;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (e.path().extension() != ".cpp" || !e.is_regular_file() || fs::equivalent(e.path(), file, ec)) continue;
    std::ifstream in(e.path(), std::ios::binary);
    if (holdsController(std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()})) return file;
  }
  return folder;
}

std::vector<fs::path> shardOf(const std::vector<fs::path>& all, int i, int n) {
  std::vector<fs::path> mine;
  for (std::size_t k = static_cast<std::size_t>(i - 1); k < all.size(); k += static_cast<std::size_t>(n)) mine.push_back(all[k]);
  return mine;
}

std::vector<Assignment> assignments() {
  std::vector<Assignment> all;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(layout().assignments, ec)) {
    if (!fs::is_regular_file(e.path() / "rubric.toml")) continue;
    Result<Rubric> r = loadRubric(e.path() / "rubric.toml");
    all.push_back({e.path().filename().string(), r ? r.value().title : r.error(), e.path() / "rubric.toml"});
  }
  std::sort(all.begin(), all.end(), [](const Assignment& a, const Assignment& b) { return a.name < b.name; });
  return all;
}

Result<fs::path> findRubric(const std::string& name) {
  for (const fs::path& candidate : {fs::path(name), fs::path(name) / "rubric.toml", layout().assignments / name / "rubric.toml"}) {
    if (fs::is_regular_file(candidate)) return candidate;
  }
  return Status::failure("unknown assignment '" + name + "': not a folder of assignments/ (see frob list), and no rubric.toml there");
}

Result<std::uint64_t> filmRun(const GradeDef& def, const fs::path& submission, const std::string& checkName, const RunGrade& run,
                              const RunOutputs& outputs) {
  const auto check = std::find_if(def.rubric.checks.begin(), def.rubric.checks.end(), [&](const Check& c) { return c.name == checkName; });
  if (check == def.rubric.checks.end()) return Status::failure("no check '" + checkName + "'");
  const std::vector<WorldRef> all = worldsOf(*check, def.secret, def.kept.value_or(KeptWorlds{}), submissionHash(submission));
  const auto ref = std::find_if(all.begin(), all.end(), [&](const WorldRef& w) { return w.name == run.world; });
  if (ref == all.end()) return Status::failure("no world '" + run.world + "' in check '" + checkName + "'");
  Result<worlds::WorldDef> world = loadWorldRef(*ref);
  if (!world) return world.status();
  Result<CompiledController> compiled = compileSubmission(submission, def.compiler);
  if (!compiled) return compiled.status();
  Result<LoadedController> controller = describeInHost(compiled.value(), def.host);
  if (!controller) return controller.status();
  Result<Summary> s = runSession({.world = world.value(),
                                  .worldName = run.world,
                                  .options = {.dt = def.rubric.dt, .seed = run.seed},
                                  .controllers = {controller.value()},
                                  .host = def.host,
                                  .seconds = check->seconds,
                                  .wholeTime = true,
                                  .outputs = outputs});
  if (!s) return s.status();
  if (s.value().failed()) return Status::failure("the run failed, so it has no video: " + s.value().robots.front().failure);
  if (s.value().trajectoryHash != run.trajectoryHash) {
    return Status::failure(format("the film's run (trajectory %016" PRIx64 ") is not the graded run (trajectory %016" PRIx64 "), so it is not shown",
                                  s.value().trajectoryHash, run.trajectoryHash));
  }
  return s.value().trajectoryHash;
}

}  // namespace frob::course
