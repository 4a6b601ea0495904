// The frob command line: thin, it parses arguments and calls the libraries.
#include "frob/base/layout.hpp"
#include "frob/grade/grade.hpp"
#include "frob/grade/judge.hpp"
#include "frob/render/output_file.hpp"
#include "frob/render/run_view.hpp"
#include "frob/run/controller_file.hpp"
#include "frob/run/examples.hpp"
#include "frob/run/format.hpp"
#include "frob/run/host.hpp"
#include "frob/run/project.hpp"
#include "frob/run/session.hpp"
#include "frob/run/summary.hpp"
#include "frob/worlds/generate.hpp"
#include "frob/worlds/registry.hpp"
#include "grade.hpp"
#include "progress.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace frob::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* kExamples = R"(Examples:
  frob run                                  the demo: BUG in the obstacle field, written to bug.mp4
  frob run my_controller.cpp --video my.mp4 compile and run your controller, watch the video
  frob run bug --seconds 30 --trace bug.csv run a course example by name, write a per-step trace
  frob run my_controller.cpp --html run.html open run.html in a browser: any instant of the run, its tasks and values
  frob run a.cpp b.cpp --world arena        one controller per robot
  frob render maze --out maze.png           a picture of a world
  frob list                                 the worlds and examples there are
  frob init my_project                      a project of your own, set up for clangd's completion
)";

// Prints "frob: <message>" on stderr and gives the exit status of a failure.
int fail(const std::string& message) {
  std::cerr << "frob: " << message << "\n";
  return 1;
}

// CPU seconds, user and system, of frob's children that have ended (and of theirs): the compiler's.
double childrenCpuSeconds() {
  rusage use{};
  getrusage(RUSAGE_CHILDREN, &use);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  return seconds(use.ru_utime) + seconds(use.ru_stime);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A world by reference name or file path.
Result<worlds::WorldDef> loadWorldNamed(const std::string& name) {
  if (worlds::findWorld(name) == nullptr && !fs::exists(name)) {
    return Status::failure("unknown world '" + name + "': not a reference world (see frob list) and no such file");
  }
  Result<worlds::WorldDef> w = worlds::findWorld(name) != nullptr ? worlds::loadReferenceWorld(name) : worlds::loadWorld(name);
  if (!w) return Status::failure(w.error());
  return *w;
}

// The world a controller names (FROB_CONTROLLER's .world): a file beside the controller, a reference
// world, a file in the working folder, or one of the course (assignments/...), in that order, so a
// starter copied anywhere still finds its world.
std::string controllerWorld(const std::string& world, const std::string& source) {
  std::error_code ec;
  const fs::path beside = fs::path(source).parent_path() / world, course = frob::layout().assignments.parent_path() / world;
  if (fs::path(world).is_absolute() || worlds::findWorld(world) != nullptr) return world;
  if (fs::is_regular_file(beside, ec)) return beside.string();
  if (!fs::exists(world, ec) && fs::is_regular_file(course, ec)) return course.string();
  return world;
}

// A controller by file (.cpp compiled, .so as it is) or by example name, as a module.
Result<course::CompiledController> compileController(const std::string& name, bool quiet, const course::CompilerSetup& setup) {
  const fs::path path(name);
  if (path.extension() == ".so") {
    if (setup.checked) return Status::failure("--check compiles the controller with its checks: give its .cpp, not " + name);
    return course::CompiledController{.module = path, .source = name};
  }
  if (path.extension() == ".cpp" || fs::exists(path)) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuBefore = childrenCpuSeconds();
    ProgressBar status(stderr, !quiet && ::isatty(STDERR_FILENO) == 1, "");
    status.say("frob: compiling " + name + (setup.checked ? " with checks" : "") + " (unless it is unchanged since its last run)...");
    Result<course::CompiledController> c = course::compileControllerFile(path, setup);
    status.finish();
    if (c && c.value().compiled && !quiet) {
      std::fputs(course::compiledNote(name, setup.checked, secondsSince(start), childrenCpuSeconds() - cpuBefore).c_str(), stderr);
    }
    return c;
  }
  if (std::optional<course::Example> e = course::findExample(name)) return course::compileExample(*e, setup);
  return Status::failure("unknown controller '" + name + "': not a file and not an example (see frob list)");
}

// The controller `name`, described by a sandboxed host or loaded into this process.
Result<course::LoadedController> loadController(const std::string& name, const std::optional<course::HostDef>& host, bool quiet) {
  Result<course::CompiledController> c = compileController(name, quiet, course::compilerSetup(host && host->checked));
  if (!c) return c.status();
  if (!host) return course::loadInProcess(c.value());
  return course::describeInHost(c.value(), *host);
}

// "960x540" into a RenderDef's size.
Status parseSize(const std::string& text, render::RenderDef& view) {
  int w = 0, h = 0;
  char x = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof()) return Status::failure("--size must look like 854x480, not '" + text + "'");
  view.width = w, view.height = h;
  return {};
}

struct RunArgs {
  std::vector<std::string> controllers;
  std::string world, size = "854x480", view = "top";
  std::optional<double> seconds;
  std::optional<std::uint64_t> seed;
  double dt = 0.01;
  double settle = 2.0;  // seconds the run goes on, the robots still, once every task returned
  int fps = 30;
  double videoMegabytes = 8.0;  // a long run's video fits in this (a grade report's film: 2 MB)
  std::optional<double> speed;
  course::RunOutputs outputs;
  std::string assignment;  // judge the run against this assignment's checks
  std::string from;        // an earlier run's trace and instant, RUN.csv#t=T: the run is that one's up to T
  bool json = false, quiet = false, sandbox = true, check = false;
};

// "PASS  visits the waypoints in order: waypoints" lines, one per criterion of each check.
std::string formatVerdicts(const std::string& assignment, const std::vector<course::CriterionVerdict>& verdicts, double ran) {
  std::string out = "Against " + assignment + "'s checks (judged as frob grade judges a run; a grade runs other worlds and seeds too):\n";
  for (const course::CriterionVerdict& v : verdicts) {
    out += std::string(v.passed ? "  PASS  " : "  FAIL  ") + v.check + ": " + v.criterion + (v.passed ? "" : ": " + v.reason);
    char judged[48] = "";
    if (v.seconds + 1e-9 < ran) std::snprintf(judged, sizeof judged, " (on its first %.1f s)", v.seconds);
    out += std::string(judged) + "\n";
    if (v.margin) out += "        " + v.margin->said(v.passed) + "\n";
  }
  return out;
}

// The summary's JSON with "assignment": {"name", "checks": [{check, criterion, seconds, passed, reason, margin}]}.
std::string withVerdicts(const std::string& json, const std::string& assignment, const std::vector<course::CriterionVerdict>& verdicts) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(json);
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (const course::CriterionVerdict& v : verdicts) {
    checks.push_back({{"check", v.check},
                      {"criterion", v.criterion},
                      {"seconds", v.seconds},
                      {"passed", v.passed},
                      {"reason", v.reason},
                      {"margin", v.margin ? nlohmann::ordered_json{{"value", v.margin->value},
                                                                   {"unit", v.margin->unit},
                                                                   {"text", v.margin->text},
                                                                   {"at", v.margin->at ? nlohmann::ordered_json(*v.margin->at) : nullptr}}
                                          : nullptr}});
  }
  doc["assignment"] = {{"name", assignment}, {"checks", checks}};
  return doc.dump(1) + "\n";
}

int runCommand(RunArgs a) {
  const bool demo = a.controllers.empty();
  if (demo) {
    a.controllers.push_back("bug");
    if (a.outputs.empty()) a.outputs.video = "bug.mp4";
    if (!a.quiet) std::fprintf(stderr, "frob: no controller given, so here is the demo: the paper's BUG algorithm (course/examples/06_bug.cpp)\n");
  }
  // The demo's video plays 4 times faster than the robot drives: two minutes of BUG in half a minute.
  a.outputs.videoBytes = static_cast<std::uint64_t>(a.videoMegabytes * 1e6);
  course::RunDef def{.options = {.dt = a.dt, .seed = a.seed}, .outputs = a.outputs, .fps = a.fps, .speed = a.speed.value_or(demo ? 4.0 : 1.0)};
  if (a.check && !a.sandbox) return fail("--check runs the controllers in their sandboxed process: leave out --no-sandbox");
  if (a.sandbox) def.host.emplace(course::HostDef{.checked = a.check});
  for (const std::string& name : a.controllers) {
    Result<course::LoadedController> c = loadController(name, def.host, a.quiet);
    if (!c) return fail(c.error());
    def.controllers.push_back(std::move(c.value()));
  }
  std::optional<course::Rubric> rubric;
  if (!a.assignment.empty()) {  // judged as a grade judges: the whole time of its longest check
    Result<fs::path> file = course::findRubric(a.assignment);
    if (!file) return fail(file.error());
    Result<course::Rubric> r = course::loadRubric(file.value());
    if (!r) return fail(r.error());
    rubric = std::move(r.value());
    def.keepRecord = def.wholeTime = true;
  }
  const ControllerOptions& defaults = def.controllers.front().entry.options;
  def.worldName = a.world.empty() ? controllerWorld(defaults.world, def.controllers.front().source) : a.world;
  Result<worlds::WorldDef> world = loadWorldNamed(def.worldName);
  if (!world) return fail(world.error());
  def.world = std::move(world.value());
  def.seconds = a.seconds.value_or(defaults.seconds);
  def.settleSeconds = a.settle;
  if (rubric && !a.seconds) {
    def.seconds = 0.0;
    for (const course::Check& c : course::checksFor(*rubric, def.worldName)) def.seconds = std::max(def.seconds, c.seconds);
  }
  if (rubric) {  // an assignment none of whose checks waits for the task to return: it is meant to run for ever
    const std::vector<course::Check> checks = course::checksFor(*rubric, def.worldName);
    def.meantToRunForever = std::none_of(checks.begin(), checks.end(), [](const course::Check& c) { return c.waitsForAReturn(); });
    def.measure = [checks](const course::RunRecord& record) { return course::measuredAlong(checks, record); };
  }
  if (Status s = parseSize(a.size, def.view); !s) return fail(s.error());
  def.view.view = a.view == "chase" ? render::ViewMode::Chase : render::ViewMode::TopDown;
  if (!a.from.empty()) {
    Result<course::ForkPoint> fork = course::readForkPoint(a.from, def.options.dt);
    if (!fork) return fail(fork.error());
    if (fork.value().at >= def.seconds)
      return fail(course::format("--from: the run ends at %.2f s, before its fork at %.2f s (--seconds)", def.seconds, fork.value().at));
    def.fork = std::move(fork.value());
  }
  if (Status s = course::validate(def); !s) return fail(s.error());

  ProgressBar bar(stderr, !a.quiet && ::isatty(STDERR_FILENO) == 1, "frob: running " + def.controllers.front().entry.name + " in " + def.worldName);
  char detail[48];
  def.progress = [&](double done) {
    std::snprintf(detail, sizeof detail, "%.1f / %.1f s", done * def.seconds, def.seconds);
    bar.show(done, detail);
  };
  def.drawing = [&](std::size_t drawn, std::size_t frames) {
    std::snprintf(detail, sizeof detail, "frame %zu / %zu", drawn, frames);
    bar.show(static_cast<double>(drawn) / static_cast<double>(frames), detail);
  };
  bar.show(0.0, "starting the controller");  // until the first step is done
  const auto start = std::chrono::steady_clock::now();
  Result<course::Summary> summary = course::runSession(def);
  const double wall = secondsSince(start);
  bar.finish();
  if (!summary) return fail(summary.error());
  const course::Summary& sum = summary.value();
  const std::vector<course::CriterionVerdict> verdicts =
      rubric ? course::judgeChecks(course::checksFor(*rubric, def.worldName), *sum.record) : std::vector<course::CriterionVerdict>{};
  if (a.json) std::cout << (rubric ? withVerdicts(course::summaryJson(sum, wall), a.assignment, verdicts) : course::summaryJson(sum, wall));
  // A layer of the sandbox that this machine could not apply is said, never skipped silently.
  if (const std::string missing = course::missingLayers(sum.sandbox); !missing.empty() && !a.quiet) {
    std::cerr << "frob: the controller ran with parts of its sandbox missing:\n" << missing;
  }
  for (const course::RobotSummary& r : sum.robots) {
    if (r.failure.empty()) continue;
    // The run up to just before the failure can be written whole: say how.
    const double before = std::floor((sum.simulatedSeconds - 1.5 * sum.dt) * 100.0) / 100.0;
    char hint[96] = "";
    if (!a.outputs.empty() && before > 0.0) std::snprintf(hint, sizeof hint, " (--seconds %.2f keeps the run up to the failure)", before);
    return fail("the controller failed: " + r.failure + "; no output files were written" + hint);
  }
  if (!a.json) std::cout << course::formatSummary(sum, wall) << (rubric ? formatVerdicts(a.assignment, verdicts, sum.simulatedSeconds) : "");
  if (demo && !a.quiet && !a.outputs.video.empty()) std::fprintf(stderr, "frob: now watch %s\n", a.outputs.video.c_str());
  return 0;
}

// The world with its robots at their starts, drawn to a PNG.
int renderCommand(const std::string& worldName, const std::string& out, const std::string& size) {
  Result<worlds::WorldDef> world = loadWorldNamed(worldName);
  if (!world) return fail(world.error());
  render::RenderDef def;
  if (Status s = parseSize(size, def); !s) return fail(s.error());
  if (Status s = render::checkWritable(out, "png"); !s) return fail(s.error());
  const worlds::Run run(world.value(), {}, {[](const Robot&) { return Behavior<Wheels>(Wheels{}); }});
  const render::RunView view(run);
  Result<render::Renderer> renderer = render::Renderer::create(def);
  if (!renderer) return fail(renderer.error());
  if (Status s = render::writePng(out, renderer.value().render(view.scene())); !s) return fail(s.error());
  std::cout << "wrote " << out << "\n";
  return 0;
}

// A generated world, written where asked.
int generateCommand(const std::string& kindName, std::uint64_t seed, const std::string& out) {
  const std::optional<worlds::WorldKind> kind = worlds::worldKind(kindName);
  if (!kind) return fail("unknown kind of world '" + kindName + "': one of " + worlds::worldKindNames());
  Result<worlds::WorldDef> world = worlds::generateWorld(*kind, seed);
  if (!world) return fail(world.error());
  if (Status s = render::checkWritable(out, "world"); !s) return fail(s.error());
  std::ofstream file(render::partialPath(out));
  file << worlds::toToml(world.value());
  file.close();
  if (!file) return fail(out + ": cannot write the world");
  if (Status s = render::commitPartial(out, "world"); !s) return fail(s.error());
  std::cout << "wrote " << out << ": " << world.value().description << "\n";
  return 0;
}

int listCommand() {
  std::cout << "Worlds (frob run --world NAME, frob render NAME):\n";
  for (const worlds::WorldEntry& w : worlds::referenceWorlds())
    std::printf("  %-10s %s\n", std::string(w.name).c_str(), std::string(w.description).c_str());
  // Where the examples and handouts are: in the source tree, or in an installed prefix's share/frob.
  const frob::Layout& files = frob::layout();
  const auto shown = [&](const fs::path& dir) { return (files.installed ? dir : fs::relative(dir, files.sourceTree)).string(); };
  std::cout << "\nExamples (frob run NAME, or frob run " << shown(files.examples) << "/NAME.cpp):\n";
  for (const course::Example& e : course::examples()) {
    Result<course::CompiledController> compiled = course::compileExample(e);
    Result<course::LoadedController> c = compiled ? course::loadInProcess(compiled.value()) : Result<course::LoadedController>(compiled.status());
    const std::string about = c ? c.value().entry.options.summary + " [" + c.value().entry.options.world + "]" : c.error();
    std::printf("  %-16s %s\n", e.name.c_str(), about.c_str());
  }
  std::cout << "\nAssignments (frob grade NAME my.cpp --visible-only; handouts in " << shown(files.assignments) << "/NAME/handout.md):\n";
  for (const course::Assignment& a : course::assignments()) std::printf("  %-16s %s\n", a.name.c_str(), a.title.c_str());
  std::cout << "\nA project of your own, with GoogleTest tests of its tasks and editor completion: frob init my_project (the template: "
            << shown(files.studentTemplate) << ")\n";
  return 0;
}

// `frob init [folder]`: the student template and the editor's flags in `folder`.
int initCommand(const std::string& folder) {
  Result<std::vector<course::ProjectFile>> files = course::initProject(folder);
  if (!files) return fail(files.error());
  for (const course::ProjectFile& f : files.value()) {
    std::cout << (f.written ? "  wrote " : "  kept   ") << f.path.string() << (f.written ? "" : " (already there)") << "\n";
  }
  std::cout << "\nRun the controller:  " << (folder == "." ? "" : "cd " + folder + " && ") << "frob run wander.cpp --video wander.mp4\n"
            << "Editor completion:   compile_flags.txt tells clangd (Debian: apt install clangd-16) where frob's headers are;\n"
            << "                     in VS Code, install the clangd extension and set \"clangd.path\": \"clangd-16\"\n";
  return 0;
}

}  // namespace

// Where a student looks for the world format: the help of every command that takes a world.
constexpr const char* kWorldHelp = "Reference world name (frob list), or a world file: TOML, its format in worlds/data/README.md";

}  // namespace frob::app

int main(int argc, char** argv) {
  CLI::App cli{"Frob Sandbox: functional reactive robot controllers, simulated headlessly", "frob"};
  cli.set_version_flag("--version", [] {
    const frob::Layout& files = frob::layout();
    return std::string("frob ") + frob::version() + "\ncompiles controllers with " + frob::course::compilerDescription() + "\nfiles in " +
           files.prefix.string() + (files.installed ? " (installed)" : " (the source tree; a build, not installed)");
  });
  cli.footer(frob::app::kExamples);
  cli.require_subcommand(0, 1);

  frob::app::RunArgs run;
  CLI::App* runCmd = cli.add_subcommand("run", "Run controllers in a world; with none, the BUG demo");
  runCmd->footer(frob::app::kExamples);
  runCmd->add_option("controllers", run.controllers, "Controller files (.cpp), or example names; one for all robots or one per robot");
  runCmd->add_option("--world", run.world, std::string(frob::app::kWorldHelp) + " (default: the controller's)");
  runCmd->add_option("--seconds", run.seconds, "Simulated seconds at most (default: the controller's)")->check(CLI::PositiveNumber);
  runCmd->add_option("--seed", run.seed, "Random seed (default: the world's)");
  runCmd->add_option("--dt", run.dt, "Simulation step, seconds")->capture_default_str()->check(CLI::Range(1e-4, 0.1));
  runCmd
      ->add_option("--settle", run.settle,
                   "Seconds the run goes on once every controller's task has returned, the robots commanded still (to see them stop)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 600.0));
  runCmd->add_option("--video", run.outputs.video, "Write an MP4 video of the run");
  runCmd
      ->add_option("--video-size", run.videoMegabytes,
                   "The video's size at most, MB: a long run's is encoded at a lower bitrate to fit (0: any size)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10000.0));
  runCmd->add_option("--frames", run.outputs.frames, "Write one PNG per video frame into this folder");
  runCmd->add_option("--plot", run.outputs.plot, "Write plots of the run (sonar, goal distance, wheels, tasks) as PNG");
  runCmd
      ->add_option("--plot-signals", run.outputs.plotSignals,
                   "More charts in --plot and --video: s0 to s15 for a sonar, or the name of a value a task "
                   "publishes with withPlot (default: every published value), e.g. s4,left")
      ->delimiter(',');
  runCmd->add_option("--trace", run.outputs.trace, "Write a CSV row per robot per step");
  runCmd->add_option(
      "--from", run.from,
      "Start from an instant of an earlier run, e.g. run.html#t=12.5 (its --html page or --trace): the world as it was then, to the last bit, "
      "with your controllers taking over (give that run's --world, --seed and --dt)");
  runCmd->add_option("--timeline", run.outputs.timeline, "Write the task timeline as JSON for ui.perfetto.dev or chrome://tracing");
  runCmd->add_option(
      "--html", run.outputs.html,
      "Write the run viewer: one page to open in a browser, with a time slider, the task stack, every value and the plots at any instant");
  runCmd->add_option("--fps", run.fps, "Frames per second of video and frames")->capture_default_str()->check(CLI::Range(1, 240));
  runCmd->add_option("--speed", run.speed, "The video plays this many times faster than simulated time (default 1; the demo 4)")
      ->check(CLI::Range(0.1, 100.0));
  runCmd->add_option("--size", run.size, "Frame size, WIDTHxHEIGHT")->capture_default_str();
  runCmd->add_option("--view", run.view, "top (from above) or chase (behind the first robot)")
      ->capture_default_str()
      ->check(CLI::IsMember({"top", "chase"}));
  runCmd->add_option("--assignment", run.assignment,
                     "Judge the run against an assignment's checks, as frob grade judges a run (e.g. go_to_goal): those that run in "
                     "this world, or all of them in a world of your own; the run lasts the longest one's time");
  runCmd->add_flag("--json", run.json, "Print the summary as JSON");
  runCmd->add_flag("--sandbox,!--no-sandbox", run.sandbox,
                   "Run the controllers in a sandboxed process of their own (the default); --no-sandbox runs them "
                   "inside frob itself, where a crash takes frob down");
  runCmd->add_flag("--check", run.check,
                   "Compile the controllers with AddressSanitizer, UndefinedBehaviorSanitizer and the C++ library's checks: an index "
                   "out of range, a use after free or an integer division by zero stops the run naming your file and line (slower)");
  runCmd->add_flag("-q,--quiet", run.quiet, "No progress bar or notes on stderr");

  std::string renderWorld, renderOut, renderSize = "960x720";
  CLI::App* renderCmd = cli.add_subcommand("render", "Draw a world with its robots at their starts to a PNG");
  renderCmd->add_option("world", renderWorld, frob::app::kWorldHelp)->required();
  renderCmd->add_option("--out", renderOut, "PNG file to write")->required();
  renderCmd->add_option("--size", renderSize, "Image size, WIDTHxHEIGHT")->capture_default_str();

  frob::app::GradeArgs grade;
  CLI::App* gradeCmd = cli.add_subcommand("grade", "Grade a submission, or a folder of them, against an assignment's rubric");
  gradeCmd->footer(R"(Examples:
  frob grade go_to_goal my.cpp --visible-only --report r.html   check your work as students may
  frob grade go_to_goal my.cpp --practice 5 --seed 7           practise the hidden checks on their family
  frob grade go_to_goal sub.cpp --results results.json --junit r.xml --logs logs/
  frob grade go_to_goal class/ --jobs 2 --out graded/           a folder per student, a gradebook and a summary
  frob grade go_to_goal class/ --out graded/ --changed         after a fix of the rubric, only those it changes
  frob grade go_to_goal class/ --jobs 2 --shard 1/4 --gradebook shard1.csv
  frob grade --merge shard1.csv shard2.csv shard3.csv shard4.csv --gradebook grades.csv
  frob grade --replay logs/reaches_the_goal__maze__3.log --secret secret.txt   a disputed run, judged again
  frob grade go_to_goal --gradescope-zip autograder.zip --secret secret.txt
Hidden seeds come from --secret FILE or $FROB_GRADE_SECRET. Exit status 0 whenever it graded.
The rubric format and the instructors' guide: course/grading.md)");
  gradeCmd->add_option("assignment", grade.assignment, "An assignment's name (assignments/NAME), folder or rubric.toml");
  gradeCmd->add_option("submission", grade.submission, "A controller file, or a folder of them (a class)");
  gradeCmd->add_option("--results", grade.results, "Write Gradescope's results.json");
  gradeCmd->add_option("--prairielearn", grade.prairielearn, "Write PrairieLearn's results.json");
  gradeCmd->add_option("--junit", grade.junit, "Write JUnit XML, a test case per check and world");
  gradeCmd->add_option("--report", grade.report, "Write one self-contained HTML page, with the first failing run's video");
  gradeCmd->add_option("--videos", grade.videos, "Keep the first failing run's video and plot in this folder");
  gradeCmd->add_option("--logs", grade.logs, "Keep each run's wheel log in this folder (for --replay)");
  gradeCmd->add_flag("--visible-only", grade.visibleOnly, "Grade only the checks students see");
  gradeCmd->add_option("--practice", grade.practice, "Grade the hidden checks' criteria in N worlds of their families, drawn from --seed")
      ->check(CLI::Range(1, 100));
  gradeCmd->add_option("--seed", grade.practiceSeed, "Your own seed for --practice (never the instructor's secret)")->capture_default_str();
  gradeCmd->add_option("--secret", grade.secret, "The instructor's secret for hidden seeds (default: $FROB_GRADE_SECRET)");
  gradeCmd->add_option("--jobs", grade.jobs, "Submissions graded at once (a class)")->capture_default_str()->check(CLI::Range(1, 256));
  gradeCmd->add_option("--shard", grade.shard, "Grade only shard I of N of the class, e.g. 2/8 (the same split on every machine)");
  CLI::Option* outOption = gradeCmd->add_option("--out", grade.out,
                                                "The class folder: DIR/gradebook.csv, a row per student, and DIR/<student>/ with their results "
                                                "and report; grading one student again replaces theirs only");
  gradeCmd
      ->add_flag("--changed", grade.changed,
                 "After a fix of the rubric: grade again only the students of --out whose result it changes (judged again from their logs)")
      ->needs(outOption);
  gradeCmd->add_option("--gradebook", grade.gradebook, "Write the class's gradebook (CSV)");
  gradeCmd->add_option("--merge", grade.merge, "Merge these shard gradebooks into --gradebook");
  gradeCmd->add_option("--replay", grade.replay,
                       "Replay a run's wheel log in the simulator and judge it again (with SUBMISSION: refused unless the log is of it)");
  gradeCmd->add_option("--student", grade.student, "Who submitted it, named in its wheel logs");
  gradeCmd->add_option("--submission-metadata", grade.submissionMetadata,
                       "Gradescope's submission_metadata.json: when it came against the due date, for a rubric's late penalty");
  gradeCmd->add_option("--gradescope-zip", grade.gradescopeZip, "Write the assignment's autograder zip for Gradescope");

  std::string kind, worldOut;
  std::uint64_t worldSeed = 1;
  CLI::App* worldCmd = cli.add_subcommand("world", "Make worlds");
  worldCmd->require_subcommand(1);
  CLI::App* generateCmd = worldCmd->add_subcommand("generate", "Make a world of a kind from a seed, checked for what its kind promises");
  generateCmd->add_option("kind", kind, frob::worlds::worldKindNames())->required();
  generateCmd->add_option("--seed", worldSeed, "The seed: the same kind and seed make the same world everywhere")->capture_default_str();
  generateCmd->add_option("--out", worldOut, "The world file to write (TOML)")->required();

  CLI::App* listCmd = cli.add_subcommand("list", "List the reference worlds and the course examples");

  std::string initFolder = ".";
  CLI::App* initCmd = cli.add_subcommand("init", "Start a controller project: the student template, and compile_flags.txt for clangd");
  initCmd->add_option("folder", initFolder, "Where (made if needed; files already there are kept)")->capture_default_str();

  CLI11_PARSE(cli, argc, argv);
  if (runCmd->parsed() || gradeCmd->parsed()) {  // off amd64, runs are close to the grader's, not the same
    utsname machine{};
    if (::uname(&machine) == 0) std::fputs(frob::course::determinismNote(machine.machine).c_str(), stderr);
  }
  if (runCmd->parsed()) return frob::app::runCommand(run);
  if (renderCmd->parsed()) return frob::app::renderCommand(renderWorld, renderOut, renderSize);
  if (gradeCmd->parsed()) return frob::app::gradeCommand(grade);
  if (generateCmd->parsed()) return frob::app::generateCommand(kind, worldSeed, worldOut);
  if (listCmd->parsed()) return frob::app::listCommand();
  if (initCmd->parsed()) return frob::app::initCommand(initFolder);
  std::cout << cli.help();
  return 0;
}
