#include "frob/run/session.hpp"

#include "frob/render/frame_log.hpp"
#include "frob/render/output_file.hpp"
#include "frob/render/run_view.hpp"
#include "frob/render/video.hpp"
#include "frob/run/diagnose.hpp"
#include "frob/run/format.hpp"
#include "run_page.hpp"
#include "session_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>

namespace frob::course {

namespace {

constexpr std::size_t kLastTasks = 5;  // ended tasks kept for the summary, per robot

// A host that could not start: its robot fails at the first step with the reason.
class Unstarted final : public worlds::ControllerDriver {
 public:
  Unstarted(std::size_t robots, std::string why) : timelines_(robots), why_(std::move(why)) {}
  void decide(const Instant&, std::span<Wheels>, std::span<Picture>, std::vector<std::pair<std::size_t, std::string>>& failed) override {
    if (!why_.empty()) failed.emplace_back(0, std::move(why_));
    why_.clear();
  }
  Timeline& timeline(std::size_t i) override { return timelines_.at(i); }

 private:
  std::vector<Timeline> timelines_;
  std::string why_;
};

// The driver of `def`'s controllers: in this process, or each robot's in a sandboxed host of its own.
worlds::DriverFactory driverFor(const RunDef& def, std::optional<RobotHosts>& hosts, bool pictures) {
  if (!def.host) {
    std::vector<Controller> controllers;
    for (const LoadedController& c : def.controllers) controllers.push_back(c.entry.make);
    return worlds::inProcess(std::move(controllers));
  }
  std::vector<std::filesystem::path> modules;
  std::vector<std::string> sources;
  std::vector<std::size_t> modulePerRobot;
  for (const LoadedController& c : def.controllers) {
    const auto known = std::find(modules.begin(), modules.end(), c.module);
    modulePerRobot.push_back(static_cast<std::size_t>(known - modules.begin()));
    if (known == modules.end()) modules.push_back(c.module), sources.push_back(c.source);
  }
  Result<RobotHosts> started = RobotHosts::start(modules, sources, modulePerRobot, def.world.robots.size(), *def.host);
  if (!started) {
    return [why = started.error()](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
      return std::make_unique<Unstarted>(sim.robotCount(), why);
    };
  }
  hosts = std::move(started.value());
  return hosts->driver(pictures);
}

// The sonar that looks straight ahead.
std::size_t frontSonarOf(const RobotSpec& spec) {
  std::size_t best = 0;
  for (std::size_t k = 0; k < spec.sonarAngles.size(); ++k) {
    if (std::abs(std::remainder(spec.sonarAngles[k], 2 * pi)) < std::abs(std::remainder(spec.sonarAngles[best], 2 * pi))) best = k;
  }
  return best;
}

const worlds::Landmark* findGoal(const worlds::WorldDef& world) {
  for (const worlds::Landmark& p : world.points) {
    if (p.name == "goal") return &p;
  }
  return nullptr;
}

render::VideoDef videoDef(const RunDef& def) {
  render::VideoDef v{.path = def.outputs.video, .width = def.view.width, .height = def.view.height, .fps = def.fps};
  if (def.outputs.videoBytes > 0) {  // a bitrate for the video's length (the run's at most) and its 1 s buffer, 5% kept for the container
    const double seconds = def.seconds / def.speed + 1.0;
    v.maxKilobitsPerSecond = std::max(1, static_cast<int>(0.95 * 8.0 * static_cast<double>(def.outputs.videoBytes) / seconds / 1000.0));
    v.preset = "veryfast";  // fewer bits for the same picture than ultrafast, at a few times its encoding time
  }
  return v;
}

// The run viewer page's heading: "wander.cpp in lounge".
std::string pageTitle(const RunDef& def) {
  std::string title;
  for (const LoadedController& c : def.controllers) {
    title += (title.empty() ? "" : ", ") + std::filesystem::path(c.source).filename().string();
  }
  return title + " in " + std::filesystem::path(def.worldName).filename().string();
}

// What a run keeps of one robot as it goes.
struct RobotWatch {
  RobotSummary summary;
  std::deque<TaskRecord> lastEnded;  // the newest kLastTasks ended tasks
  std::vector<TaskRecord> all;       // every task, when a timeline or page is written
  std::optional<double> returnedAt;  // when a task at the top last returned
  std::optional<Point2> previous;    // last true position
};

}  // namespace

bool Summary::failed() const {
  for (const RobotSummary& r : robots) {
    if (!r.failure.empty()) return true;
  }
  return false;
}

// "s4" names sonar 4.
std::optional<std::size_t> sonarSignal(const std::string& name) {
  if (name.size() < 2 || name[0] != 's' || !std::all_of(name.begin() + 1, name.end(), ::isdigit) || name.size() > 4) return std::nullopt;
  return static_cast<std::size_t>(std::stoul(name.substr(1)));
}

Status validate(const RunDef& def) {
  const std::size_t robots = def.world.robots.size();
  if (Status s = worlds::checkRunnable(def.world); !s) return Status::failure(def.worldName + ": " + s.error());
  if (def.controllers.empty()) return Status::failure("no controller given");
  if (def.controllers.size() != 1 && def.controllers.size() != robots) {
    return Status::failure("the world '" + def.worldName + "' has " + std::to_string(robots) +
                           " robots: give one controller for all of them or one per robot (" + std::to_string(def.controllers.size()) + " given)");
  }
  if (!(def.seconds > 0.0) || !std::isfinite(def.seconds)) return Status::failure("--seconds must be a positive number of seconds");
  if (!(def.options.dt > 0.0) || def.options.dt > 0.1) return Status::failure("--dt must be a step in (0, 0.1] seconds");
  if (def.fps <= 0 || def.fps > 240) return Status::failure("--fps must be between 1 and 240");
  if (!(def.speed >= 0.1 && def.speed <= 100.0)) return Status::failure("--speed must be between 0.1 and 100");
  const RunOutputs& out = def.outputs;
  if (!out.video.empty() || !out.frames.empty() || !out.plot.empty()) {
    if (Status s = render::validate(def.view); !s) return s;
  }
  if (!out.video.empty()) {
    if (Status s = render::validate(videoDef(def)); !s) return s;
  }
  if (!out.frames.empty()) {
    Status s = std::filesystem::is_directory(out.frames) ? render::validateOutputDirectory(out.frames) : render::checkWritable(out.frames, "frames");
    if (!s) return s;
  }
  for (const std::string& name : out.plotSignals) {
    const std::size_t ring = def.world.robots.empty() ? 0 : worlds::robotSpec(def.world.robots.front()).sonarAngles.size();
    if (const std::optional<std::size_t> k = sonarSignal(name); k && *k >= ring) {
      return Status::failure("--plot-signals: there is no sonar " + name + ": the ring has " + std::to_string(ring) + " (s0 to s" +
                             std::to_string(ring - 1) + ")");
    }
  }
  for (const auto& [path, what] : {std::pair{out.plot, "plot"}, {out.trace, "trace"}, {out.timeline, "timeline"}, {out.html, "html"}}) {
    if (path.empty()) continue;
    if (Status s = render::checkWritable(path, what); !s) return s;
  }
  for (const LoadedController& c : def.controllers) {
    if (def.host ? c.module.empty() : !c.entry.make) {
      return Status::failure("the controller '" + c.source + "' " + (def.host ? "has no module to run in a sandbox" : "cannot run in this process"));
    }
  }
  return {};
}

// The plots of a run: the front sonar, the goal and the wheels, then the signals asked for.
render::RunViewDef viewDef(const RunDef& def) {
  render::RunViewDef view{.plotSeconds = def.seconds};
  if (def.outputs.plotSignals.empty()) return view;
  view.published.emplace();
  for (const std::string& name : def.outputs.plotSignals) {
    if (const std::optional<std::size_t> k = sonarSignal(name)) {
      view.signals.push_back({"sonar " + std::to_string(*k) + " (m)", [k = *k](const worlds::StepRecord& rec) { return rec.robots[0].sonar[k]; }});
    } else {
      view.published->push_back(name);
    }
  }
  return view;
}

Result<Summary> runSession(const RunDef& def) {
  if (Status s = validate(def); !s) return s;
  const RunOutputs& out = def.outputs;
  const bool drawFrames = !out.video.empty() || !out.frames.empty();
  const bool allTasks = !out.timeline.empty() || !out.html.empty();
  std::optional<RobotHosts> hosts;
  // Every step is read as it comes (summary, trace, frames, plots, page), so only the newest is kept.
  worlds::DriverFactory drivers = driverFor(def, hosts, drawFrames || !out.plot.empty() || !out.html.empty());
  if (def.fork) drivers = forkedAt(*def.fork, std::move(drivers));
  worlds::Run run(def.world, def.options, drivers, {.window = 1});
  const worlds::Simulation& sim = run.simulation();
  const std::size_t n = sim.robotCount();
  const bool checked = def.host && def.host->checked;

  // Outputs, opened before the first step so that a bad path fails at once.
  std::optional<render::RunView> view;
  if (drawFrames || !out.plot.empty()) view.emplace(run, viewDef(def));
  std::optional<render::Renderer> renderer;
  if (drawFrames || !out.plot.empty()) {
    Result<render::Renderer> r = render::Renderer::create(def.view);
    if (!r) return r.status();
    renderer.emplace(std::move(r.value()));
  }
  std::optional<render::VideoWriter> video;
  if (!out.video.empty()) {
    Result<render::VideoWriter> v = render::VideoWriter::open(videoDef(def));
    if (!v) return v.status();
    video.emplace(std::move(v.value()));
  }
  std::optional<FrameFolder> frames;
  if (!out.frames.empty()) {
    Result<FrameFolder> f = FrameFolder::open(out.frames);
    if (!f) return f.status();
    frames.emplace(std::move(f.value()));
  }
  std::optional<TraceFile> trace;
  if (!out.trace.empty()) {
    std::size_t sonars = 0;
    for (std::size_t i = 0; i < n; ++i) sonars = std::max(sonars, sim.spec(i).sonarAngles.size());
    Result<TraceFile> t = TraceFile::open(out.trace, sonars);
    if (!t) return t.status();
    trace.emplace(std::move(t.value()));
  }
  std::optional<RunPage> page;
  if (!out.html.empty()) {
    Result<RunPage> p = RunPage::open(out.html, sim, def.view.sonarHalfAngle);
    if (!p) return p.status();
    page.emplace(std::move(p.value()));
  }
  // Nothing half-written stays behind when the run stops early.
  auto discard = [&] {
    if (frames) frames->discard();
  };

  const worlds::Landmark* goal = findGoal(sim.world());
  Diagnosis diagnosis(sim.walls(), sim.world().size, sim.dt());
  std::vector<RobotWatch> watch(n);
  for (std::size_t i = 0; i < n; ++i) {
    const LoadedController& c = def.controllers.size() == 1 ? def.controllers.front() : def.controllers[i];
    watch[i].summary.name = sim.robotName(i);
    watch[i].summary.controller = c.entry.name + " (" + c.source + ")";
  }

  std::optional<double> allFinishedAt;  // when the last controller's task returned: the settle time begins
  std::optional<RunRecorder> recorder;
  if (def.keepRecord) recorder.emplace(sim, sim.world());
  const render::FramePicker picker(sim.dt(), def.fps / def.speed);  // frames per simulated second
  render::FrameLog film;                                            // drawn once the run is over, so that the controllers step as in an unfilmed run
  while (sim.time() + 0.5 * sim.dt() < def.seconds && run.failures().empty()) {
    const std::int64_t step = sim.stepCount();
    run.step();
    const worlds::StepRecord& rec = run.recorder().steps().back();
    if (recorder) recorder->stepped(sim);
    bool allFinished = true;
    for (std::size_t i = 0; i < n; ++i) {
      RobotWatch& w = watch[i];
      const worlds::RobotRecord& r = rec.robots[i];
      const Point2 at = r.truePose.position;
      if (w.previous) w.summary.distance += (at - *w.previous).norm();
      w.previous = at;
      w.summary.collisions += static_cast<int>(r.bumps.size());
      if (goal != nullptr) {
        const double d = (at - goal->position).norm();
        w.summary.goalDistance = std::min(d, w.summary.goalDistance.value_or(d));
        if (d <= kGoalRadius && !w.summary.goalTime) w.summary.goalTime = rec.time;
      }
      Timeline& timeline = run.timeline(i);
      const RobotSpec& spec = sim.spec(i);
      diagnosis.observe(i, rec.time, r.truePose, r.wheels, r.sonar.empty() ? spec.sonarMaxRange : r.sonar[frontSonarOf(spec)], spec.sonarMaxRange);
      for (TaskRecord& ended : timeline.drainEnded()) {
        diagnosis.taskEnded(i, ended);
        if (recorder) recorder->taskEnded(i, ended, sim.time());
        if (ended.parent < 0 && ended.how == TaskEnd::Returned) w.returnedAt = ended.end;
        if (allTasks) w.all.push_back(ended);
        w.lastEnded.push_back(std::move(ended));
        if (w.lastEnded.size() > kLastTasks) w.lastEnded.pop_front();
      }
      // Done (its task returned, a stop for ever): not merely a task at the top that returned, as
      // in a behavior that runs a task and then goes on.
      if (!w.summary.finishedAt && run.finished(i)) w.summary.finishedAt = w.returnedAt.value_or(rec.time);
      if (trace) trace->row(rec.time, i, r, timeline.current());
      allFinished = allFinished && w.summary.finishedAt.has_value();
    }
    if (view) view->update(run);
    if (page) page->step(rec);
    for (int k = drawFrames ? picker.framesAt(step) : 0; k > 0; --k) film.note(*view);
    if (def.progress) def.progress(std::min(1.0, sim.time() / def.seconds));
    if (allFinished && !def.wholeTime) {
      if (!allFinishedAt) {
        allFinishedAt = 0.0;
        for (const RobotWatch& w : watch) allFinishedAt = std::max(*allFinishedAt, *w.summary.finishedAt);
        if (view) view->setNote(format("every task returned at %.2f s: commanded still", *allFinishedAt));
      }
      if (sim.time() + 0.5 * sim.dt() >= *allFinishedAt + def.settleSeconds) break;
    }
  }

  Summary summary{.world = def.worldName,
                  .seed = sim.seed(),
                  .dt = sim.dt(),
                  .simulatedSeconds = sim.time(),
                  .settledSeconds = allFinishedAt && def.settleSeconds > 0 ? sim.time() - *allFinishedAt : 0.0,
                  .steps = sim.stepCount(),
                  .trajectoryHash = run.recorder().trajectoryHash()};
  if (hosts) summary.notes = hosts->notes(), summary.sandbox = hosts->layers();
  if (def.fork) {
    summary.notes.push_back(format("the run up to %.2f s is %s's, played back step by step; the controllers took over at %.2f s", def.fork->at,
                                   def.fork->source.c_str(), def.fork->at));
  }
  if (view) {
    for (const std::string& name : def.outputs.plotSignals) {
      const std::vector<std::string>& seen = view->publishedNames();
      if (!sonarSignal(name) && std::find(seen.begin(), seen.end(), name) == seen.end()) {
        summary.notes.push_back("--plot-signals: no task published '" + name + "' (withPlot(\"" + name + "\", behavior, task))");
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    RobotWatch& w = watch[i];
    w.summary.lastTasks.assign(w.lastEnded.begin(), w.lastEnded.end());
    const std::vector<TaskRecord> running = run.timeline(i).running();
    w.summary.hints = diagnosis.hints(i, w.summary.name, running, sim.time(), def.meantToRunForever);
    // A run that looks stuck may be a silent bug: say how to look for one.
    const bool stuck = w.summary.distance < kNeverMoved || (w.lastEnded.empty() && running.size() > 1);
    if (stuck && !checked) {
      w.summary.hints.push_back(w.summary.name + (w.summary.distance < kNeverMoved ? " never moved" : "'s first task never ended") +
                                ", and this run was not checked: frob run --check stops at an index out of range, a use after free or an integer "
                                "division by zero, naming your file and line");
    }
    for (TaskRecord r : running) {
      r.end = sim.time();  // its bar ends with the run; the page shows it as still running
      if (allTasks) w.all.push_back(r);
      w.summary.lastTasks.push_back(std::move(r));
    }
    summary.robots.push_back(std::move(w.summary));
  }
  for (const worlds::ControllerFailure& f : run.failures()) {
    summary.robots.at(f.robot).failure = f.message;
  }
  if (recorder) summary.record = std::move(*recorder).finish(run.failures());
  const std::vector<Measured> measured = def.measure && summary.record ? def.measure(*summary.record) : std::vector<Measured>{};
  if (summary.failed()) {
    discard();  // the video and trace are dropped with their writers
    return summary;
  }

  // What the assignment measures, charted for the video and the plot: the first robot's, as the
  // other charts are, with the band it wants marked.
  std::vector<render::Plot> judged;
  for (const Measured& m : measured) {
    if (m.robot != 0) continue;
    render::Plot& chart = judged.emplace_back(
        render::Plot{.title = "judged: " + m.name, .series = {{m.name + " (" + m.unit + ")", {}, green}}, .yMin = {}, .yMax = {}, .levels = {}});
    const auto every = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(0.05 / m.dt)));  // as RunView samples
    for (std::size_t k = 0; k < m.values.size(); k += every) chart.series[0].samples.push_back({static_cast<double>(k) * m.dt, m.values[k]});
    for (const std::optional<double>& b : {m.low, m.high}) {
      if (b) chart.levels.push_back(*b);
    }
  }
  if (drawFrames) {
    render::Image image;
    std::size_t drawn = 0;
    Status s = film.replay(
        *view,
        [&](const render::FrameScene& scene, const render::PlotSet& plots) {
          renderer->renderInto(scene, plots, image);
          Status written = video ? video->write(image) : Status();
          if (written && frames) written = frames->write(image);
          if (def.drawing) def.drawing(++drawn, film.size());
          return written;
        },
        judged);
    if (!s) return discard(), s;
  }

  // Complete: move every file into place.
  if (video) {
    if (Status s = video->close(); !s) return discard(), s;
    summary.written.push_back(out.video);
  }
  if (frames) summary.written.push_back(out.frames + " (" + std::to_string(frames->count()) + " frames)");
  if (trace) {
    if (Status s = trace->commit(measured); !s) return s;
    summary.written.push_back(out.trace);
  }
  std::vector<std::vector<TaskRecord>> tasks;
  for (RobotWatch& w : watch) tasks.push_back(std::move(w.all));
  if (!out.timeline.empty()) {
    std::vector<std::string> names;
    for (const RobotSummary& r : summary.robots) names.push_back(r.name);
    if (Status s = writeTimeline(out.timeline, names, tasks); !s) return s;
    summary.written.push_back(out.timeline);
  }
  if (page) {
    RunPageEnd end{.title = pageTitle(def),
                   .subtitle = format("seed %llu, %.2f s in %lld steps, trajectory %016llx.", (unsigned long long)summary.seed,
                                      summary.simulatedSeconds, (long long)summary.steps, (unsigned long long)summary.trajectoryHash),
                   .tasks = std::move(tasks),
                   .measured = measured};
    for (const RobotSummary& r : summary.robots) end.controllers.push_back(r.controller), end.finishedAt.push_back(r.finishedAt);
    Result<std::uint64_t> bytes = page->write(end);
    if (!bytes) return bytes.status();
    summary.written.push_back(format("%s (%.0f kB)", out.html.c_str(), static_cast<double>(bytes.value()) / 1000.0));
  }
  if (!out.plot.empty()) {
    render::PlotSet plots = view->plots();
    plots.tEnd = summary.simulatedSeconds;  // the time axis ends where the run ended
    plots.plots.insert(plots.plots.end(), judged.begin(), judged.end());
    if (Status s = render::writePng(out.plot, renderer->renderPlots(plots)); !s) return s;
    summary.written.push_back(out.plot);
  }
  return summary;
}

}  // namespace frob::course
