#include "frob/render/run_view.hpp"

#include "frob/errors.hpp"

#include <algorithm>
#include <limits>

namespace frob::render {

namespace {

constexpr double kWallThickness = 0.05;  // thin walls are Box2D segments; drawn this wide, metres

void addWall(FrameScene& s, const worlds::WallDef& w) {
  worlds::forEachEdge(
      w,
      [&](const Point2& a, const Point2& b) {
        s.walls.push_back({a, b, kWallThickness});
      },
      [&](const Point2& p, const Point2& q) {
        const Point2 lo = p.cwiseMin(q), hi = p.cwiseMax(q);
        s.blocks.push_back({(lo + hi) / 2, (hi - lo) / 2, 0.0});
      },
      [&](const Point2& centre, double radius) {
        s.pillars.push_back({centre, radius});
      });
}

// Appends `p` to a path that keeps points at least `spacing` apart, plus the newest position as a
// loose last point that the next call replaces (so the path always ends at the robot).
void extendPath(std::vector<Point2>& path, char& loose, const Point2& p, double spacing) {
  if (path.empty()) {
    path.push_back(p);
    loose = 0;
    return;
  }
  const Point2& kept = loose && path.size() >= 2 ? path[path.size() - 2] : path.back();
  const bool keep = (p - kept).norm() >= spacing;
  if (loose)
    path.back() = p;
  else
    path.push_back(p);
  loose = keep ? 0 : 1;
}

}  // namespace

FrameScene staticScene(const worlds::Simulation& sim) {
  FrameScene s;
  const worlds::WorldDef& world = sim.world();
  s.bounds = {Point2(0, 0), Point2(world.size.x(), world.size.y())};
  for (const worlds::WallDef& w : sim.walls()) addWall(s, w);
  for (const worlds::Landmark& p : world.points) s.points.push_back({p.name, p.position, {}});
  return s;
}

RunView::RunView(const worlds::Run& run, RunViewDef def) : def_(std::move(def)) {
  const worlds::Simulation& sim = run.simulation();
  scene_ = staticScene(sim);
  const std::size_t n = sim.robotCount();
  for (std::size_t i = 0; i < n; ++i) {
    RobotView r;
    r.name = sim.robotName(i);
    r.spec = sim.spec(i);
    r.pose = sim.truePose(i);
    r.odometry = sim.odometry(i);
    scene_.robots.push_back(std::move(r));
  }
  pathHeadLoose_.assign(n, 0);
  odomHeadLoose_.assign(n, 0);
  scene_.time = sim.time();

  // The charts: "range" (front sonar, distance to the goal), "wheels", then one per extra signal.
  if (def_.plotRobot < n) {
    frontSonar_ = def_.frontSonar ? frontSonarIndex(sim.spec(def_.plotRobot)) : -1;
    if (!def_.goal.empty()) goal_ = worlds::findPoint(sim.world(), def_.goal);
    if (frontSonar_ >= 0 || goal_) {
      Plot range{.title = "range (gaps: no echo)", .series = {}, .yMin = 0.0, .yMax = {}, .levels = {}};
      if (frontSonar_ >= 0) {
        sonarSlot_ = {plots_.plots.size(), range.series.size()};
        range.series.push_back({"front sonar (m)", {}, {}});
      }
      if (goal_) {
        goalSlot_ = {plots_.plots.size(), range.series.size()};
        range.series.push_back({"to " + def_.goal + " (m)", {}, {}});
      }
      plots_.plots.push_back(std::move(range));
    }
    if (def_.wheels) {
      forwardSlot_ = {plots_.plots.size(), 0};
      turnSlot_ = {plots_.plots.size(), 1};
      plots_.plots.push_back({"wheels", {{"forward (m/s)", {}, {}}, {"turn (rad/s)", {}, {}}}, {}, {}, {}});
    }
    for (const RunSignal& s : def_.signals) {
      signalSlots_.push_back({plots_.plots.size(), 0});
      plots_.plots.push_back({s.name, {{s.name, {}, {}}}, {}, {}, {}});
    }
  }
  plots_.tStart = 0.0;
  plots_.tEnd = def_.plotSeconds;
}

void RunView::takeInstant(const worlds::StepRecord& rec) {
  FROB_ASSERT(rec.robots.size() == scene_.robots.size(), "RunView: the run's robot count changed");
  for (std::size_t i = 0; i < rec.robots.size(); ++i) {
    const worlds::RobotRecord& r = rec.robots[i];
    RobotView& v = scene_.robots[i];
    extendPath(v.path, pathHeadLoose_[i], r.truePose.position, def_.pathSpacing);
    extendPath(v.odometryPath, odomHeadLoose_[i], r.odometry.position, def_.pathSpacing);
  }
  // Plot samples at most every sampleSeconds: a chart shows a few hundred of them anyway.
  if (def_.plotRobot >= rec.robots.size()) return;
  if (sampled_ && rec.time < lastSample_ + def_.sampleSeconds - 1e-9) return;
  sampled_ = true;
  lastSample_ = rec.time;
  const worlds::RobotRecord& r = rec.robots[def_.plotRobot];
  auto add = [&](Slot s, double v) { plots_.plots[s.plot].series[s.series].samples.push_back({rec.time, v}); };
  if (frontSonar_ >= 0 && static_cast<std::size_t>(frontSonar_) < r.sonar.size()) {  // no echo: a gap, so the scale is the echoes'
    const double range = r.sonar[static_cast<std::size_t>(frontSonar_)];
    add(sonarSlot_, range < scene_.robots[def_.plotRobot].spec.sonarMaxRange ? range : std::numeric_limits<double>::quiet_NaN());
  }
  if (goal_) add(goalSlot_, (r.truePose.position - *goal_).norm());
  if (def_.wheels) {
    add(forwardSlot_, r.wheels.forward);
    add(turnSlot_, r.wheels.turn);
  }
  for (std::size_t k = 0; k < def_.signals.size(); ++k) {
    if (def_.signals[k].value) add(signalSlots_[k], def_.signals[k].value(rec));
  }
  for (const Shape& s : r.picture.shapes()) {
    if (s.kind != Shape::Kind::Value) continue;
    auto [known, added] = publishedPlots_.try_emplace(s.text, std::string::npos);
    if (added) {  // a new name: its chart, when asked for
      publishedNames_.push_back(s.text);
      if (!def_.published || std::find(def_.published->begin(), def_.published->end(), s.text) != def_.published->end()) {
        known->second = plots_.plots.size();
        plots_.plots.push_back({s.text, {{s.text, {}, s.color}}, {}, {}, {}});
      }
    }
    if (known->second != std::string::npos) add({known->second, 0}, s.value);
  }
}

void RunView::markTasks(const worlds::Run& run, double now) {
  if (def_.plotRobot >= scene_.robots.size()) return;
  const std::vector<TaskRecord> running = run.timeline(def_.plotRobot).running();
  if (running.empty()) {
    lastTaskId_ = -1;
    return;
  }
  const TaskRecord& inner = running.back();
  if (inner.id == lastTaskId_) return;
  // A task that started since the last look is marked at its start; a parent that runs again
  // (its child ended) has an older start, so it is marked now.
  const bool started = inner.id > lastTaskId_;
  double t = started ? inner.start : now;
  if (!plots_.taskMarks.empty()) t = std::max(t, plots_.taskMarks.back().t);
  plots_.taskMarks.push_back({t, inner.name});
  lastTaskId_ = inner.id;
}

void RunView::update(const worlds::Run& run) {
  // The instants since the last update are the newest of those the recorder keeps.
  const std::vector<worlds::StepRecord>& steps = run.recorder().steps();
  const auto fresh = static_cast<std::size_t>(run.recorder().count() - taken_);
  FROB_ASSERT(fresh <= steps.size(), "RunView: the run must keep every step since the last update (RecorderOptions)");
  if (fresh == 0) return;
  for (std::size_t k = steps.size() - fresh; k < steps.size(); ++k) takeInstant(steps[k]);
  taken_ = run.recorder().count();
  const worlds::StepRecord& last = steps.back();
  scene_.time = last.time;
  for (std::size_t i = 0; i < last.robots.size(); ++i) {
    const worlds::RobotRecord& r = last.robots[i];
    RobotView& v = scene_.robots[i];
    v.pose = r.truePose;
    v.odometry = r.odometry;
    v.sonar = r.sonar;
    v.bumps = r.bumps;
    v.wheels = r.wheels;
    v.picture = r.picture;
    v.task = run.timeline(i).current();
  }
  markTasks(run, last.time);
}

}  // namespace frob::render
