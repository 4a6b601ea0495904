#include "frob/grade/grade.hpp"

#include "frob/grade/judge.hpp"
#include "frob/grade/wheel_log.hpp"
#include "frob/run/diagnose.hpp"
#include "frob/run/format.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/world_file.hpp"
#include "runs.hpp"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace frob::course {

namespace fs = std::filesystem;

using namespace detail;

namespace {

// The time now, UTC, as JUnit's timestamp has it: 2026-12-02T21:58:37 (a report's timing field).
std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

// How drive() runs: `meantToRunForever`, no hint that a task never ended; `keepWheels`, every
// step's wheels kept (for a log).
struct Driving {
  bool meantToRunForever = false;
  bool keepWheels = false;
};

// Steps `run` for `steps` steps, or until a controller fails, keeping every robot's true path,
// contacts and reported result.
Ran drive(worlds::Run& run, const worlds::WorldDef& world, std::int64_t steps, Driving how = {}) {
  const worlds::Simulation& sim = run.simulation();
  Ran ran;
  RunRecorder recorder(sim, world);
  Diagnosis diagnosis(sim.walls(), world.size, sim.dt());
  for (std::int64_t k = 0; k < steps && run.failures().empty(); ++k) {
    run.step();
    if (how.keepWheels) ran.wheels.push_back(run.commands());
    recorder.stepped(sim);
    for (std::size_t i = 0; i < sim.robotCount(); ++i) {
      const SensorFrame& frame = sim.frame(i);
      const double front = frame.sonar.empty() ? sim.spec(i).sonarMaxRange : frame.sonar[0];  // sonar 0 looks ahead
      diagnosis.observe(i, sim.time(), sim.truePose(i), run.commands()[i], front, sim.spec(i).sonarMaxRange);
      for (const TaskRecord& ended : run.timeline(i).drainEnded()) {
        diagnosis.taskEnded(i, ended);
        recorder.taskEnded(i, ended, sim.time());
      }
    }
  }
  ran.record = std::move(recorder).finish(run.failures());
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    for (std::string& h : diagnosis.hints(i, sim.robotName(i), run.timeline(i).running(), sim.time(), how.meantToRunForever))
      ran.hints.push_back(std::move(h));
  }
  ran.trajectoryHash = run.recorder().trajectoryHash();
  return ran;
}

std::int64_t stepsFor(double seconds, double dt) { return static_cast<std::int64_t>(std::floor(seconds / dt + 0.5)); }

// A run passes when no controller failed and every criterion holds; else the first reason. Every
// criterion is judged, for its margin.
void judgeRun(const Check& check, const RunRecord& record, RunGrade& out) {
  for (const Track& t : record.robots) {
    if (!t.failure.empty()) {
      out.reason = "the controller failed: " + t.failure;
      out.kind = "the controller failed";
      return;
    }
  }
  for (const Criterion& c : check.criteria) {
    Verdict v = judge(c, record);
    if (!v.passed && out.reason.empty()) {
      out.reason = v.reason;
      out.kind = "it failed the rubric's \"" + std::string(toString(c.kind)) + "\" criterion";
    }
    out.criteria.push_back({.check = check.name,
                            .criterion = std::string(toString(c.kind)),
                            .seconds = check.seconds,
                            .passed = v.passed,
                            .reason = std::move(v.reason),
                            .margin = std::move(v.margin)});
  }
  out.passed = out.reason.empty();
}

// Wheels logged by a grading, played back in order; after the last, a stop.
class ReplayDriver final : public worlds::ControllerDriver {
 public:
  ReplayDriver(std::size_t robots, const std::vector<std::vector<Wheels>>& wheels) : wheels_(wheels), timelines_(robots) {}
  void decide(const Instant& now, std::span<Wheels> out, std::span<Picture>, std::vector<std::pair<std::size_t, std::string>>&) override {
    const auto k = static_cast<std::size_t>(now.step);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = k < wheels_.size() && i < wheels_[k].size() ? wheels_[k][i] : Wheels{};
  }
  Timeline& timeline(std::size_t i) override { return timelines_.at(i); }

 private:
  const std::vector<std::vector<Wheels>>& wheels_;
  std::vector<Timeline> timelines_;
};

// A log's file name: the check, world and seed, in letters a file system takes.
std::string logName(const std::string& check, const std::string& world, std::uint64_t seed) {
  std::string name = check + "__" + fs::path(world).stem().string() + "__" + std::to_string(seed);
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
  }
  return name + ".log";
}

// The log of a run, signed with the secret when there is one (wheel_log.hpp), written whole; false
// when it could not be.
bool writeLog(const fs::path& path, const GradeDef& def, const Check& check, const WorldRef& world, std::uint64_t seed, const Ran& ran,
              const Grade& g) {
  // The rubric by its assignment's folder, so that the log replays wherever the assignment is.
  WheelLog log{.rubric = (fs::absolute(def.rubric.file).parent_path().filename() / def.rubric.file.filename()).string(),
               .check = check.name,
               .world = world.name,
               .generated = world.generated ? std::string(toString(*world.generated)) : std::string(),
               .worldSeed = world.worldSeed,
               .seed = seed,
               .submission = g.submission,
               .submissionHash = g.submissionHash,
               .student = def.student,
               .trajectory = ran.trajectoryHash,
               .robots = ran.record.robots.size(),
               .wheels = ran.wheels};
  for (std::size_t i = 0; i < ran.record.robots.size(); ++i) {
    const Track& t = ran.record.robots[i];
    if (!t.failure.empty()) log.failures.emplace_back(i, t.failure);
    if (t.returned) log.returnedAt.emplace_back(i, t.returnedAt), log.returned.emplace_back(i, *t.returned);
  }
  const std::string text = wheelLogText(log, def.secret);
  const fs::path partial = path.string() + ".partial";
  std::ofstream(partial, std::ios::binary) << text;
  std::error_code ec;
  if (fs::file_size(partial, ec) == text.size()) fs::rename(partial, path, ec);
  return !ec && fs::exists(path);
}

}  // namespace

namespace detail {

RunKey runKey(const Check& check, const WorldRef& ref, std::uint64_t seed, double dt) {
  return {ref.generated ? toString(*ref.generated) : ref.name, ref.worldSeed, seed, stepsFor(check.seconds, dt), !check.waitsForAReturn()};
}

void runCheck(const GradeDef& def, const CompiledController& compiled, const Check& check, const WorldRef& ref, const worlds::WorldDef& world,
              RunGrade& r, Grade& g, SharedRuns* shared) {
  const RunKey key = runKey(check, ref, r.seed, def.rubric.dt);
  const bool judgedAgain = shared != nullptr && --shared->judges[key] > 0;  // a later check judges this run too
  const Ran* ran = nullptr;
  if (shared != nullptr) {
    if (const auto known = shared->made.find(key); known != shared->made.end()) ran = &known->second;
  }
  std::optional<Ran> own;
  if (ran == nullptr) {
    std::optional<RunCores::Held> core;  // the core of its own this run of a class holds
    if (def.runCores) core.emplace(def.runCores->take());
    // What a controller prints in a check students do not see goes nowhere: it could print what it
    // senses in a hidden world, for whoever reads frob's output (a CI log) to see.
    const bool seen = check.visibility == Visibility::Visible;
    HostDef host = def.host;
    if (!seen) host.output = [](std::string_view) {};
    Result<RobotHosts> hosts = RobotHosts::start({compiled.module}, {compiled.source}, {0}, world.robots.size(), host);
    if (!hosts) {
      r.reason = hosts.error();
      r.kind = "the controller's program could not start";
      if (isGraderFailure(hosts.status())) g.graderFailure = hosts.error();
      return;
    }
    worlds::Run run(world, {.dt = def.rubric.dt, .seed = r.seed}, hosts.value().driver(false), {.keepSteps = false});
    Ran made =
        drive(run, world, stepsFor(check.seconds, def.rubric.dt), {.meantToRunForever = !check.waitsForAReturn(), .keepWheels = !def.logs.empty()});
    for (std::string& n : seen ? hosts.value().notes() : std::vector<std::string>{}) {  // "printed more than 1 MB" is a bit of it too
      if (std::find(g.notes.begin(), g.notes.end(), n) == g.notes.end()) g.notes.push_back(std::move(n));
    }
    g.sandboxMissing = missingLayers(hosts.value().layers());
    ran = judgedAgain ? &shared->made.emplace(key, std::move(made)).first->second : &own.emplace(std::move(made));
  }
  judgeRun(check, ran->record, r);
  r.trajectoryHash = ran->trajectoryHash;
  r.hints = ran->hints;
  if (!def.logs.empty()) {
    std::error_code ec;
    fs::create_directories(def.logs, ec);
    r.log = def.logs / logName(check.name, ref.name, r.seed);
    if (!writeLog(r.log, def, check, ref, r.seed, *ran, g)) g.graderFailure = std::string(kGraderFailure) + "cannot write the log " + r.log.string();
  }
  if (shared != nullptr && !judgedAgain) shared->made.erase(key);
}

std::string fileText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace detail

namespace {

// How one run of a check is made: runs `r` (its world and seed set) into `r` and `g`.
using RunMaker = std::function<void(const Check& check, const WorldRef& ref, const worlds::WorldDef& world, RunGrade& r, Grade& g)>;

// `g`'s checks, each of its runs made by `make` (after `failed`, a reason that stands for every run),
// then the scores, the leaderboard and the lateness: grading and judging again share it.
// One check's runs, each made by `make` (or failed for `failed`), and its score.
CheckGrade scoreCheck(const GradeDef& def, const Check& check, const KeptWorlds& kept, std::map<std::string, Result<worlds::WorldDef>>& loaded,
                      Grade& g, const RunMaker& make, const std::string& failed) {
  CheckGrade cg{.name = check.name, .points = check.points, .visibility = check.visibility};
  const std::vector<std::uint64_t> seeds = seedsOf(check, def.secret);
  for (const WorldRef& w : worldsOf(check, def.secret, kept, g.submissionHash)) {
    const std::string key = w.generated ? std::string(toString(*w.generated)) + " " + std::to_string(w.worldSeed) : w.name;
    auto known = loaded.find(key);
    if (known == loaded.end()) known = loaded.emplace(key, loadWorldRef(w)).first;
    const Result<worlds::WorldDef>& world = known->second;
    for (std::uint64_t seed : seeds) {
      if (!g.graderFailure.empty()) break;
      RunGrade& r = cg.runs.emplace_back(
          RunGrade{.world = w.name, .seed = seed, .generator = w.generated ? format("%s --seed %" PRIu64, toString(*w.generated), w.worldSeed) : ""});
      if (!failed.empty()) {
        r.reason = r.kind = failed;
      } else if (!world) {
        r.reason = "the world could not be loaded: " + world.error();
        r.kind = "the world could not be loaded";
      } else {
        const auto began = std::chrono::steady_clock::now();
        make(check, w, world.value(), r, g);
        r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      }
    }
  }
  const auto passed = std::count_if(cg.runs.begin(), cg.runs.end(), [](const RunGrade& r) { return r.passed; });
  cg.score = cg.runs.empty() ? 0.0 : check.points * static_cast<double>(passed) / static_cast<double>(cg.runs.size());
  return cg;
}

void scoreChecks(const GradeDef& def, Grade& g, const RunMaker& make, const std::string& failed = {}) {
  // Loaded once per world, not per name: two checks' "hidden world 1" are different draws.
  std::map<std::string, Result<worlds::WorldDef>> loaded;
  const KeptWorlds kept = def.kept.value_or(KeptWorlds{});
  // Every visible check's runs before any other's: whatever a controller could carry from one run to
  // the next (what the kernel caches, a file's access time) never brings a hidden world into a run
  // students see. The grades stay in the rubric's order.
  std::vector<std::optional<CheckGrade>> made(def.rubric.checks.size());
  for (const bool seen : {true, false}) {
    for (std::size_t i = 0; i < def.rubric.checks.size(); ++i) {
      const Check& check = def.rubric.checks[i];
      if ((check.visibility == Visibility::Visible) != seen || (def.visibleOnly && !seen)) continue;
      if (!g.graderFailure.empty()) break;  // no grade: nothing more to run
      made[i] = scoreCheck(def, check, kept, loaded, g, make, failed);
    }
  }
  for (std::optional<CheckGrade>& c : made) {
    if (c) g.checks.push_back(std::move(*c));
  }
  for (const LeaderboardMetric& m : def.rubric.leaderboard) g.leaderboard.push_back(leaderboardValue(m, g));
  // Lateness takes its share of what the checks earned, for each day or part of one.
  if (def.daysLate && *def.daysLate > 0 && def.rubric.latePerDay > 0) {
    const double days = std::ceil(*def.daysLate - 1e-9), share = std::min(def.rubric.lateMost, def.rubric.latePerDay * days);
    g.latePenalty = share * g.score();
    g.notes.push_back(format("submitted %.0f day%s late: %s of the score taken (%g%% a day begun, at most %g%%)", days, days == 1 ? "" : "s",
                             (std::to_string(static_cast<int>(std::lround(100 * share))) + "%").c_str(), 100 * def.rubric.latePerDay,
                             100 * def.rubric.lateMost));
  }
}

// The wheels of `log` played back in `world` for `steps` steps, with what the controller reported.
Ran replayed(const WheelLog& log, const worlds::WorldDef& world, double dt, std::int64_t steps) {
  const auto factory = [&](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    return std::make_unique<ReplayDriver>(sim.robotCount(), log.wheels);
  };
  worlds::Run run(world, {.dt = dt, .seed = log.seed}, factory, {.keepSteps = false});
  Ran ran = drive(run, world, steps);
  for (const auto& [i, why] : log.failures) ran.record.robots.at(i).failure = why;
  for (const auto& [i, value] : log.returned) ran.record.robots.at(i).returned = value;
  for (const auto& [i, at] : log.returnedAt) ran.record.robots.at(i).returnedAt = at;
  return ran;
}

}  // namespace

Grade grade(const GradeDef& def, const fs::path& submission) { return gradeWith(def, submission, hiddenWorldsOf(def)); }

Result<KeptWorlds> detail::hiddenWorldsOf(const GradeDef& def) {
  return def.kept ? *def.kept : def.visibleOnly ? KeptWorlds{} : fairHiddenWorlds(def);  // the visible checks alone need none
}

Grade detail::gradeWith(const GradeDef& def, const fs::path& submission, const Result<KeptWorlds>& kept) {
  const auto start = std::chrono::steady_clock::now();
  Grade g{.assignment = def.assignment, .submission = submission.string(), .submissionHash = submissionHash(submission), .startedAt = utcNow()};
  std::string messages;
  Result<CompiledController> compiled = compileSubmission(submission, def.compiler, &messages);
  if (!compiled)
    (isGraderFailure(compiled.status()) ? g.graderFailure : g.compileError) = compiled.error() + (messages.empty() ? "" : "\n" + messages);
  GradeDef checked = def;
  if (kept) {
    checked.kept = kept.value();
  } else if (isGraderFailure(kept.status())) {
    if (g.graderFailure.empty()) g.graderFailure = kept.error();  // no grade stands on hidden worlds no one could check
  } else {
    g.notes.push_back("the hidden worlds were not checked against the reference solution: " + kept.error());
  }
  SharedRuns shared;
  for (const Check& check : checked.rubric.checks) {
    if (checked.visibleOnly && check.visibility != Visibility::Visible) continue;
    for (const WorldRef& w : worldsOf(check, checked.secret, checked.kept.value_or(KeptWorlds{}), g.submissionHash))
      for (std::uint64_t seed : seedsOf(check, checked.secret)) ++shared.judges[runKey(check, w, seed, checked.rubric.dt)];
  }
  scoreChecks(
      checked, g,
      [&](const Check& check, const WorldRef& ref, const worlds::WorldDef& world, RunGrade& r, Grade& out) {
        runCheck(def, compiled.value(), check, ref, world, r, out, &shared);
      },
      compiled ? "" : "the submission did not compile");
  g.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return g;
}

std::optional<Grade> rejudge(const GradeDef& def, const fs::path& submission, const fs::path& logs) {
  Grade g{.assignment = def.assignment, .submission = submission.string(), .submissionHash = submissionHash(submission), .startedAt = utcNow()};
  bool complete = true;
  scoreChecks(def, g, [&](const Check& check, const WorldRef& ref, const worlds::WorldDef& world, RunGrade& r, Grade&) {
    if (!complete) return;
    // The run as graded: its log, signed with this secret, of this submission in this world with this
    // seed, as long as the rubric now runs it (or ended sooner by the controller's failure).
    Result<WheelLog> log = readWheelLog(fileText(logs / logName(check.name, ref.name, r.seed)), def.secret);
    const std::int64_t steps = stepsFor(check.seconds, def.rubric.dt);
    complete =
        log && log.value().check == check.name && log.value().world == ref.name && log.value().seed == r.seed &&
        log.value().submissionHash == g.submissionHash && log.value().robots == world.robots.size() &&
        log.value().generated == (ref.generated ? std::string(toString(*ref.generated)) : std::string()) && log.value().worldSeed == ref.worldSeed &&
        (std::cmp_equal(log.value().wheels.size(), steps) || (std::cmp_less(log.value().wheels.size(), steps) && !log.value().failures.empty()));
    if (!complete) return;
    const Ran ran = replayed(log.value(), world, def.rubric.dt, static_cast<std::int64_t>(log.value().wheels.size()));
    complete = ran.trajectoryHash == log.value().trajectory;  // else the simulator has changed: only a new run can tell
    judgeRun(check, ran.record, r);
    r.trajectoryHash = ran.trajectoryHash;
    r.hints = ran.hints;
    r.log = logs / logName(check.name, ref.name, r.seed);
  });
  if (!complete) return std::nullopt;
  return g;
}

Result<Replay> replay(const fs::path& file, const std::string& secret, const fs::path& submission) {
  if (!fs::is_regular_file(file)) return Status::failure(file.string() + ": cannot open the log");
  Result<WheelLog> read = readWheelLog(fileText(file), secret);
  if (!read) return Status::failure(file.string() + ": " + read.error());
  WheelLog& log = read.value();
  if (!submission.empty() && submissionHash(submission) != log.submissionHash) {
    return Status::failure(file.string() + ": this is the log of another submission (" + log.submission + ", SHA-256 " + log.submissionHash +
                           (log.student.empty() ? "" : ", " + log.student) + "), not of " + submission.string() + " (SHA-256 " +
                           submissionHash(submission) + ")");
  }
  const std::string& rubricFile = log.rubric;
  const std::string& checkName = log.check;
  const std::string& worldName = log.world;
  std::optional<WorldRef> generated;
  if (!log.generated.empty()) {
    const std::optional<worlds::WorldKind> kind = worlds::worldKind(log.generated);
    if (!kind) return Status::failure(file.string() + ": not a wheel log of frob grade (no world kind '" + log.generated + "')");
    generated = WorldRef{.generated = kind, .worldSeed = log.worldSeed};
  }
  const std::uint64_t seed = log.seed, graded = log.trajectory;
  const std::size_t steps = log.wheels.size(), robots = log.robots;
  const auto bad = [&](const std::string& what) { return Status::failure(file.string() + ": not a wheel log of frob grade (" + what + ")"); };
  // Named by its assignment's folder (logs of before: the rubric's absolute path): found beside the
  // log or in a folder above it, else as frob grade finds an assignment (the working folder, assignments/).
  Result<fs::path> found = fs::path(rubricFile);
  if (!fs::path(rubricFile).is_absolute()) {
    std::error_code ec;
    found = findRubric(fs::path(rubricFile).parent_path().string());
    for (fs::path d = fs::absolute(file, ec).parent_path(); d.has_relative_path(); d = d.parent_path()) {
      if (fs::is_regular_file(d / rubricFile, ec)) {
        found = d / rubricFile;
        break;
      }
    }
  }
  if (!found) return Status::failure(file.string() + ": its rubric " + rubricFile + " is neither beside it nor here: " + found.error());
  Result<Rubric> rubric = loadRubric(found.value());
  if (!rubric) return rubric.status();
  const auto check = std::find_if(rubric.value().checks.begin(), rubric.value().checks.end(), [&](const Check& c) { return c.name == checkName; });
  if (check == rubric.value().checks.end()) return Status::failure(rubricFile + ": has no check '" + checkName + "' any more");
  // A generated world comes back from its kind and seed (a hidden one's seed is the secret's, not in the rubric).
  const auto ref = std::find_if(check->worlds.begin(), check->worlds.end(), [&](const WorldRef& w) { return w.name == worldName; });
  if (!generated && ref == check->worlds.end())
    return Status::failure(rubricFile + ": check '" + checkName + "' has no world '" + worldName + "' any more");
  Result<worlds::WorldDef> world = loadWorldRef(generated ? *generated : *ref);
  if (!world) return world.status();
  if (world.value().robots.size() != robots) return bad("the world now has another number of robots");

  const Ran ran = replayed(log, world.value(), rubric.value().dt, static_cast<std::int64_t>(steps));
  if (ran.trajectoryHash != graded) {
    return Status::failure(file.string() + format(": replaying it gives the trajectory %016" PRIx64 ", not the graded run's %016" PRIx64
                                                  " (the simulator has changed since)",
                                                  ran.trajectoryHash, graded));
  }
  Replay r{.check = checkName,
           .submission = log.submission,
           .submissionHash = log.submissionHash,
           .student = log.student,
           .run = {.world = worldName, .seed = seed, .trajectoryHash = ran.trajectoryHash, .log = file}};
  judgeRun(*check, ran.record, r.run);
  return r;
}

}  // namespace frob::course
