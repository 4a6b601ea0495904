#include "frob/render/frame_log.hpp"

#include "frob/assert.hpp"

#include <algorithm>

namespace frob::render {

namespace {

// `path` as it was when it had `count` points, the last at `end`: kept points never move, only the last.
void pathThen(std::vector<Point2>& out, const std::vector<Point2>& now, std::size_t count, const Point2& end) {
  out.clear();
  if (count == 0) return;
  out.insert(out.end(), now.begin(), now.begin() + static_cast<std::ptrdiff_t>(count - 1));
  out.push_back(end);
}

}  // namespace

void FrameLog::note(const RunView& view) {
  const FrameScene& scene = view.scene();
  Frame f{.time = scene.time, .note = scene.note, .robots = {}, .taskMarks = view.plots().taskMarks.size(), .samples = {}};
  for (std::size_t i = 0; i < scene.robots.size(); ++i) {
    const RobotView& r = scene.robots[i];
    Robot kept{.pose = r.pose,
               .odometry = r.odometry,
               .sonar = r.sonar,
               .bumps = r.bumps,
               .path = r.path.size(),
               .odometryPath = r.odometryPath.size(),
               .pathEnd = r.path.empty() ? Point2::Zero() : r.path.back(),
               .odometryPathEnd = r.odometryPath.empty() ? Point2::Zero() : r.odometryPath.back(),
               .picture = {},
               .task = r.task,
               .wheels = r.wheels};
    // A picture usually stays for many frames: share the last one while it is the same.
    const std::shared_ptr<const Picture>& last = frames_.empty() ? nullptr : frames_.back().robots[i].picture;
    kept.picture = last && *last == r.picture ? last : std::make_shared<const Picture>(r.picture);
    f.robots.push_back(std::move(kept));
  }
  for (const Plot& p : view.plots().plots) {
    for (const Series& s : p.series) f.samples.push_back(static_cast<std::uint32_t>(s.samples.size()));
  }
  frames_.push_back(std::move(f));
}

Status FrameLog::replay(const RunView& end, const std::function<Status(const FrameScene&, const PlotSet&)>& draw,
                        const std::vector<Plot>& more) const {
  FrameScene scene = end.scene();
  const PlotSet& all = end.plots();
  PlotSet plots{.plots = {}, .taskMarks = {}, .tStart = all.tStart, .tEnd = all.tEnd};
  for (const Frame& f : frames_) {
    FROB_ASSERT(f.robots.size() == scene.robots.size(), "FrameLog: the view's robot count changed");
    scene.time = f.time;
    scene.note = f.note;
    for (std::size_t i = 0; i < f.robots.size(); ++i) {
      const Robot& r = f.robots[i];
      RobotView& v = scene.robots[i];
      const RobotView& last = end.scene().robots[i];
      v.pose = r.pose;
      v.odometry = r.odometry;
      v.sonar = r.sonar;
      v.bumps = r.bumps;
      pathThen(v.path, last.path, r.path, r.pathEnd);
      pathThen(v.odometryPath, last.odometryPath, r.odometryPath, r.odometryPathEnd);
      v.picture = *r.picture;
      v.task = r.task;
      v.wheels = r.wheels;
    }
    plots.taskMarks.assign(all.taskMarks.begin(), all.taskMarks.begin() + static_cast<std::ptrdiff_t>(f.taskMarks));
    // Charts only ever appear (a value first published), and each series only grows.
    std::size_t k = 0;
    for (std::size_t p = 0; p < all.plots.size() && k < f.samples.size(); ++p) {
      const Plot& whole = all.plots[p];
      if (plots.plots.size() <= p) plots.plots.push_back({whole.title, {}, whole.yMin, whole.yMax, whole.levels});
      Plot& shown = plots.plots[p];
      shown.series.resize(whole.series.size());
      for (std::size_t s = 0; s < whole.series.size(); ++s, ++k) {
        shown.series[s].name = whole.series[s].name;
        shown.series[s].color = whole.series[s].color;
        shown.series[s].samples.assign(whole.series[s].samples.begin(), whole.series[s].samples.begin() + f.samples[k]);
      }
    }
    const std::size_t noted = plots.plots.size();
    for (const Plot& m : more) {  // drawn below the noted charts, up to this frame's instant
      Plot& shown = plots.plots.emplace_back(Plot{m.title, {}, m.yMin, m.yMax, m.levels});
      for (const Series& s : m.series) {
        const auto upTo = std::upper_bound(s.samples.begin(), s.samples.end(), f.time + 1e-9, [](double t, const Sample& v) { return t < v.t; });
        shown.series.push_back(Series{s.name, std::vector<Sample>(s.samples.begin(), upTo), s.color});
      }
    }
    const Status s = draw(scene, plots);
    plots.plots.resize(noted);
    if (!s) return s;
  }
  return {};
}

}  // namespace frob::render
